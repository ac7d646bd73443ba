#include "analysis/diffraction/matrix_psf.h"

#include <algorithm>
#include <complex>
#include <stdexcept>
#include <vector>

#include "math/constants.h"

namespace lenslab {

Psf matrix_psf(const PupilFunction& pupil, const ImageGrid& grid) {
    if (grid.size < 1) throw std::invalid_argument("a PSF grid needs at least one sample");
    if (!(grid.spacing > 0)) throw std::invalid_argument("a PSF grid's spacing must be positive");
    using Complex = std::complex<double>;
    // Only the rows and columns the pupil covers carry light.
    const int first = pupil.size / 2 - pupil.samples / 2, n = pupil.samples, m = grid.size;
    std::vector<Complex> field(static_cast<size_t>(n) * n);
    double total = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const size_t cell = pupil.index(first + i, first + j);
            const double a = pupil.amplitude[cell];
            field[static_cast<size_t>(i) * n + j] = std::polar(a, 2 * kPi * pupil.opd_waves[cell]);
            total += a;
        }
    if (!(total > 0)) throw std::invalid_argument("no light passes the pupil");
    const double scale = -2 * kPi / (2 * pupil.wavelength * pupil.f_number);
    Psf psf;
    psf.size = m;
    psf.spacing = grid.spacing;
    psf.cutoff = pupil.cutoff_frequency();
    // The kernels: row k for image coordinate k, column j for pupil coordinate j.
    const auto kernel = [&](double centre) {
        std::vector<Complex> e(static_cast<size_t>(m) * n);
        for (int k = 0; k < m; ++k)
            for (int j = 0; j < n; ++j)
                e[static_cast<size_t>(k) * n + j] = std::polar(
                    1.0, scale * (centre + psf.coordinate(k)) * pupil.coordinate(first + j));
        return e;
    };
    const std::vector<Complex> ex = kernel(grid.centre_x), ey = kernel(grid.centre_y);
    // T = P · Exᵀ (n × m), then U = Ey · T (m × m).
    std::vector<Complex> t(static_cast<size_t>(n) * m, 0.0);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < m; ++k) {
            Complex sum = 0;
            for (int j = 0; j < n; ++j)
                sum += field[static_cast<size_t>(i) * n + j] * ex[static_cast<size_t>(k) * n + j];
            t[static_cast<size_t>(i) * m + k] = sum;
        }
    psf.intensity.assign(static_cast<size_t>(m) * m, 0.0);
    for (int l = 0; l < m; ++l)
        for (int k = 0; k < m; ++k) {
            Complex sum = 0;
            for (int i = 0; i < n; ++i)
                sum += ey[static_cast<size_t>(l) * n + i] * t[static_cast<size_t>(i) * m + k];
            psf.intensity[static_cast<size_t>(l) * m + k] = std::norm(sum) / (total * total);
        }
    psf.strehl = *std::max_element(psf.intensity.begin(), psf.intensity.end());
    return psf;
}

}  // namespace lenslab
