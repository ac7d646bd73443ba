#include "analysis/diffraction/pupil_function.h"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "math/cholesky.h"

namespace lenslab {

PupilFunction make_pupil(const PupilSampling& sampling, double wavelength, double f_number,
                         const std::function<double(double x, double y)>& opd_waves,
                         double apodisation) {
    if (sampling.samples <= 0 || sampling.samples % 2 != 0)
        throw std::invalid_argument("pupil samples must be a positive even number");
    if (sampling.padding < 2)
        throw std::invalid_argument("pupil padding must be at least 2 (Nyquist-sampled PSF)");
    if (!(wavelength > 0) || !(f_number > 0))
        throw std::invalid_argument("pupil wavelength and F-number must be positive");
    PupilFunction p;
    p.samples = sampling.samples;
    p.size = sampling.samples * sampling.padding;
    p.wavelength = wavelength;
    p.f_number = f_number;
    const size_t n = static_cast<size_t>(p.size) * p.size;
    p.amplitude.assign(n, 0.0);
    p.opd_waves.assign(n, 0.0);
    // Only the rows and columns the pupil covers need visiting.
    const int first = p.size / 2 - p.samples / 2, last = first + p.samples;
    for (int i = first; i < last; ++i) {
        const double y = p.coordinate(i);
        for (int j = first; j < last; ++j) {
            const double x = p.coordinate(j);
            const double rho2 = x * x + y * y;
            if (rho2 > 1.0) continue;
            p.amplitude[p.index(i, j)] = std::exp(-apodisation * rho2);
            p.opd_waves[p.index(i, j)] = opd_waves(x, y);
        }
    }
    return p;
}

WavefrontTilt remove_tilt(PupilFunction& pupil) {
    std::vector<double> gram(9, 0.0), rhs(3, 0.0);
    for (int i = 0; i < pupil.size; ++i)
        for (int j = 0; j < pupil.size; ++j) {
            const size_t cell = pupil.index(i, j);
            if (!(pupil.amplitude[cell] > 0)) continue;
            const double basis[3] = {1.0, pupil.coordinate(j), pupil.coordinate(i)};
            for (int a = 0; a < 3; ++a) {
                rhs[a] += basis[a] * pupil.opd_waves[cell];
                for (int b = 0; b < 3; ++b) gram[a * 3 + b] += basis[a] * basis[b];
            }
        }
    const std::optional<std::vector<double>> plane = solve_cholesky(gram, rhs);
    if (!plane) throw std::invalid_argument("too few rays pass to measure the wavefront's tilt");
    const WavefrontTilt tilt{(*plane)[1], (*plane)[2]};
    for (int i = 0; i < pupil.size; ++i)
        for (int j = 0; j < pupil.size; ++j)
            pupil.opd_waves[pupil.index(i, j)] -=
                tilt.x * pupil.coordinate(j) + tilt.y * pupil.coordinate(i);
    return tilt;
}

double wavefront_rms(const PupilFunction& pupil) {
    // Two passes (mean, then spread) so a large piston does not cancel the variance away.
    double weights = 0, mean = 0;
    for (size_t k = 0; k < pupil.amplitude.size(); ++k) {
        const double weight = pupil.amplitude[k] * pupil.amplitude[k];
        weights += weight;
        mean += weight * pupil.opd_waves[k];
    }
    if (weights == 0) return 0;
    mean /= weights;
    double variance = 0;
    for (size_t k = 0; k < pupil.amplitude.size(); ++k) {
        const double d = pupil.opd_waves[k] - mean;
        variance += pupil.amplitude[k] * pupil.amplitude[k] * d * d;
    }
    return std::sqrt(variance / weights);
}

}  // namespace lenslab
