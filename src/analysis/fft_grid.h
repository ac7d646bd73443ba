#pragma once
// A square grid of complex samples in FFTW-aligned memory, transformed in place. FFTW's
// plans are made once per size and kept: planning is not thread-safe, so it happens
// under a lock; executing a plan on new arrays is (FFTW manual, section 5.4 "Thread
// safety" and 4.6 "New-array execute functions").

#include <complex>
#include <cstddef>

namespace lenslab {

class FftGrid {
public:
    explicit FftGrid(int size);  // zero-filled
    ~FftGrid();
    FftGrid(const FftGrid&) = delete;
    FftGrid& operator=(const FftGrid&) = delete;

    int size() const { return size_; }
    std::complex<double>& operator()(int i, int j) {
        return data_[static_cast<size_t>(i) * size_ + j];
    }
    const std::complex<double>& operator()(int i, int j) const {
        return data_[static_cast<size_t>(i) * size_ + j];
    }
    // Unnormalised 2-D forward DFT, X[k] = Σ x[n] exp(-i 2π k·n / size), in place. When
    // only rows [first_row, first_row + rows) hold non-zero samples (a padded pupil), saying
    // so skips the others' transforms.
    void forward(int first_row = 0, int rows = -1);

private:
    int size_;
    std::complex<double>* data_;
};

}  // namespace lenslab
