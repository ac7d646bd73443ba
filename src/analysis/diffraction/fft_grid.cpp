#include "analysis/diffraction/fft_grid.h"

#include <fftw3.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <new>
#include <stdexcept>
#include <utility>

namespace lenslab {
namespace {

// In-place forward transforms of `rows` contiguous rows of length `size`, one plan per
// (size, rows), made with FFTW_ESTIMATE (microseconds, leaves the arrays alone, the same plan
// every run) on aligned scratch memory and executed on other grids.
fftw_plan row_plan_for(int size, int rows) {
    static std::mutex fft_plan_mutex;
    // Never destroyed, so the plans stay reachable (no leak reports) until the process ends.
    static auto* const fft_plans = new std::map<std::pair<int, int>, fftw_plan>;
    const std::lock_guard lock(fft_plan_mutex);
    const auto key = std::make_pair(size, rows);
    auto found = fft_plans->find(key);
    if (found != fft_plans->end()) return found->second;
    fftw_complex* scratch = fftw_alloc_complex(static_cast<size_t>(size) * rows);
    if (!scratch) throw std::bad_alloc();
    const int n[1] = {size};
    fftw_plan plan = fftw_plan_many_dft(1, n, rows, scratch, nullptr, 1, size, scratch, nullptr, 1,
                                        size, FFTW_FORWARD, FFTW_ESTIMATE);
    fftw_free(scratch);
    if (!plan) throw std::runtime_error("FFTW could not plan a transform");
    fft_plans->emplace(key, plan);
    return plan;
}

// Square in-place transpose, in tiles that stay in cache.
void transpose_square(std::complex<double>* data, int size) {
    constexpr int tile = 32;
    for (int bi = 0; bi < size; bi += tile)
        for (int bj = bi; bj < size; bj += tile)
            for (int i = bi; i < std::min(bi + tile, size); ++i)
                for (int j = std::max(bj, i + 1); j < std::min(bj + tile, size); ++j)
                    std::swap(data[static_cast<size_t>(i) * size + j],
                              data[static_cast<size_t>(j) * size + i]);
}

}  // namespace

FftGrid::FftGrid(int size) : size_(size) {
    if (size <= 0) throw std::invalid_argument("FFT grid size must be positive");
    const size_t n = static_cast<size_t>(size) * size;
    data_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(n));
    if (!data_) throw std::bad_alloc();
    std::fill(data_, data_ + n, std::complex<double>(0.0, 0.0));
}

FftGrid::~FftGrid() { fftw_free(data_); }

void FftGrid::forward_transposed(int first_row, int rows) {
    if (rows < 0) first_row = 0, rows = size_;
    if (first_row < 0 || first_row + rows > size_)
        throw std::invalid_argument("FFT row band outside the grid");
    // Rows, then columns as rows of the transpose: FFTW_ESTIMATE's plans for strided columns
    // are several times slower than a transpose and contiguous rows. Rows known to be zero
    // transform to zero and are skipped. std::complex<double> has fftw_complex's layout (FFTW
    // manual, section 4.1.1); a whole number of complex elements keeps the plan's alignment.
    auto* d = reinterpret_cast<fftw_complex*>(data_);
    if (rows > 0) {
        fftw_complex* band = d + static_cast<size_t>(first_row) * size_;
        fftw_execute_dft(row_plan_for(size_, rows), band, band);
    }
    transpose_square(data_, size_);
    fftw_execute_dft(row_plan_for(size_, size_), d, d);
}

}  // namespace lenslab
