#include "analysis/diffraction/huygens_psf.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "math/constants.h"

namespace lenslab {

Psf huygens_psf(const FieldWavefront& w, const HuygensGrid& grid) {
    if (grid.size < 1) throw std::invalid_argument("a Huygens PSF needs at least one sample");
    if (grid.spacing < 0) throw std::invalid_argument("a Huygens PSF's spacing must be positive");
    const PupilFunction& pupil = w.pupil;
    Psf psf;
    psf.size = grid.size;
    psf.spacing = grid.spacing > 0 ? grid.spacing : 0.5 * pupil.wavelength * pupil.f_number;
    psf.cutoff = pupil.cutoff_frequency();
    psf.intensity.assign(static_cast<size_t>(grid.size) * grid.size, 0.0);

    // Each source's complex amplitude and its place against the reference point.
    struct Source {
        std::complex<double> amplitude;
        Vec3 offset;  // S − Q
    };
    std::vector<Source> sources;
    sources.reserve(w.sphere_points.size());
    double total = 0;
    for (const FieldWavefront::SpherePoint& s : w.sphere_points) {
        const double a = pupil.amplitude[s.cell];
        sources.push_back({std::polar(a, 2 * kPi * pupil.opd_waves[s.cell]), s.at - w.reference});
        total += a;
    }
    if (!(total > 0)) throw std::invalid_argument("no light passes the pupil");
    const double k = 2 * kPi * w.image_index / pupil.wavelength;
    const double radius = w.reference_radius;

    tbb::parallel_for(0, grid.size, [&](int i) {
        for (int j = 0; j < grid.size; ++j) {
            const Vec3 d{grid.centre_x + psf.coordinate(j), grid.centre_y + psf.coordinate(i),
                         0.0};  // P − Q
            std::complex<double> field = 0;
            for (const Source& s : sources) {
                // |P − S| − R without the cancellation of two nearly equal lengths.
                const Vec3 ps = d - s.offset;
                const double distance = length(ps);
                const double excess = (dot(d, d) - 2 * dot(d, s.offset)) / (distance + radius);
                field += s.amplitude * std::polar(radius / distance, k * excess);
            }
            psf.intensity[static_cast<size_t>(i) * grid.size + j] =
                std::norm(field) / (total * total);
        }
    });
    psf.strehl = *std::max_element(psf.intensity.begin(), psf.intensity.end());
    return psf;
}

}  // namespace lenslab
