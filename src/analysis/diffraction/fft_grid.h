#pragma once
// A square grid of complex samples in FFTW-aligned memory, transformed in place. FFTW's
// plans are made once per size and kept: planning is not thread-safe, so it happens
// under a lock; executing a plan on new arrays is (FFTW manual, section 5.4 "Thread
// safety" and 4.6 "New-array execute functions").

#include <algorithm>
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
    // Unnormalised 2-D forward DFT, X[k] = Σ x[n] exp(-i 2π k·n / size), in place and left
    // transposed: afterwards (i, j) holds X[j][i] (read_centred undoes that for free). When
    // only rows [first_row, first_row + rows) hold non-zero samples (a padded pupil), saying
    // so skips the others' transforms.
    void forward_transposed(int first_row = 0, int rows = -1);

    // After forward_transposed: out[i·size + j] = f(X[i - size/2][j - size/2]) (indices
    // modulo size), the spectrum with zero frequency at the centre. In tiles, so the
    // transposed reads stay in cache.
    template <class T, class F>
    void read_centred(T* out, F f) const {
        constexpr int tile = 16;
        const int m = size_, h = size_ / 2;
        const auto shifted = [&](int k) { return k + h < m ? k + h : k + h - m; };
        for (int b_row = 0; b_row < m; b_row += tile)
            for (int b_col = 0; b_col < m; b_col += tile)
                for (int r = b_row; r < std::min(b_row + tile, m); ++r) {
                    // Storage row r is X's column r.
                    const size_t column = static_cast<size_t>(shifted(r));
                    for (int c = b_col; c < std::min(b_col + tile, m); ++c)
                        out[static_cast<size_t>(shifted(c)) * m + column] =
                            f(data_[static_cast<size_t>(r) * m + c]);
                }
    }

private:
    int size_;
    std::complex<double>* data_;
};

}  // namespace lenslab
