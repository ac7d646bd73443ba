#include "analysis/fft_grid.h"

#include <fftw3.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <new>
#include <stdexcept>

namespace lenslab {
namespace {

// One in-place forward plan per size, made with FFTW_ESTIMATE (which leaves the arrays alone
// and takes microseconds) on aligned scratch memory and executed on other aligned grids.
fftw_plan forward_plan_for(int size) {
    static std::mutex fft_plan_mutex;
    static std::map<int, fftw_plan> fft_plans;
    const std::lock_guard lock(fft_plan_mutex);
    auto found = fft_plans.find(size);
    if (found != fft_plans.end()) return found->second;
    fftw_complex* scratch = fftw_alloc_complex(static_cast<size_t>(size) * size);
    if (!scratch) throw std::bad_alloc();
    fftw_plan plan = fftw_plan_dft_2d(size, size, scratch, scratch, FFTW_FORWARD, FFTW_ESTIMATE);
    fftw_free(scratch);
    if (!plan) throw std::runtime_error("FFTW could not plan a 2-D transform");
    fft_plans.emplace(size, plan);
    return plan;
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

void FftGrid::forward() {
    // std::complex<double> has fftw_complex's layout (FFTW manual, section 4.1.1).
    auto* d = reinterpret_cast<fftw_complex*>(data_);
    fftw_execute_dft(forward_plan_for(size_), d, d);
}

}  // namespace lenslab
