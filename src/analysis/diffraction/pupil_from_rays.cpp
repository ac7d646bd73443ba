#include "analysis/diffraction/pupil_from_rays.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/aberrations/aberrations.h"
#include "analysis/system/paraxial.h"
#include "analysis/system/real_ray.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

// Optical path along a traced ray from its start to its last point: segment k runs in the
// medium in front of surface k.
double path_through(const OpticalSystem& system, const RealRay& ray, double nm) {
    double path = 0;
    for (size_t k = 0; k + 1 < ray.points.size(); ++k)
        path += std::abs(system.n_before(k, nm)) * length(ray.points[k + 1] - ray.points[k]);
    return path;
}

}  // namespace

RayWavefront::RayWavefront(const OpticalSystem& system, const RayPupilOptions& options)
    : sampling_(options.sampling) {
    if (system.has_grin()) {
        throw SceneError("objects",
                         "wavefront figures (OPD, PSF, MTF) are not computed through "
                         "gradient-index lenses: the optical path along their curved rays is "
                         "not measured yet");
    }
    // make_pupil checks the sampling; an empty OPD costs one pass over the grid.
    const PupilFunction grid = make_pupil(sampling_, 1, 1, [](double, double) { return 0.0; });
    const double nm = options.wavelength_nm;
    const ParaxialResult paraxial = paraxial_trace(system, nm);
    aperture_radius_ =
        options.aperture_radius > 0 ? options.aperture_radius : usable_aperture_radius(system, nm);
    paraxial_focus_z_ = paraxial.z_rear_focus;
    f_number_ = std::abs(paraxial.efl) / (2 * aperture_radius_);
    wavelength_ = nm / options.nm_per_length_unit;
    pupil_z_ = options.pupil_z.value_or(system.last_vertex());
    image_index_ = std::abs(system.n_after(system.surfaces.size() - 1, nm));
    const double travel = system.image_travel();

    const double z0 = beam_start_z(system);
    const IndexRatios ratios = index_ratios(system, nm);
    const auto trace = [&](double x, double y, size_t cell, TracedRay* out) {
        const RealRay r = trace_real_ray(system, {{x, y, z0}, {0, 0, 1}}, ratios);
        if (r.fate != RayFate::Passed || !(r.direction.z * travel > 0)) return false;
        *out = {cell, r.exit_point(), r.direction, path_through(system, r, nm)};
        return true;
    };
    if (!trace(0, 0, 0, &axial_)) throw std::invalid_argument("the axial ray does not pass");
    for (int i = 0; i < grid.size; ++i)
        for (int j = 0; j < grid.size; ++j) {
            const size_t cell = grid.index(i, j);
            if (grid.amplitude[cell] == 0) continue;
            TracedRay ray;
            if (!trace(grid.coordinate(j) * aperture_radius_, grid.coordinate(i) * aperture_radius_,
                       cell, &ray))
                continue;
            rays_.push_back(ray);
            // Where the ray crosses the axis (its meridional plane holds the axis).
            const double h = std::hypot(ray.point.x, ray.point.y);
            // Its slope towards the axis per unit of travel along it.
            const double slope = -(ray.point.x * ray.direction.x + ray.point.y * ray.direction.y) /
                                 (h * ray.direction.z * travel);
            if (h > 0 && slope > 0) {
                const double z_cross = ray.point.z + travel * h / slope;
                focus_span_ = std::max(focus_span_, std::abs(z_cross - paraxial_focus_z_));
            }
        }
    if (rays_.empty()) throw std::invalid_argument("no ray passes the system");
}

std::optional<double> RayWavefront::path_to_sphere(const TracedRay& ray, double image_z) const {
    // |p + t d - C| = |R|: of the two crossings take the one nearer the pupil (the other
    // lies beyond the image point).
    const Vec3 q = ray.point - Vec3{0, 0, image_z};
    const double radius = image_z - pupil_z_;
    const double b = dot(q, ray.direction);
    const double c = dot(q, q) - radius * radius;
    const double disc = b * b - c;
    if (disc < 0) return std::nullopt;
    const double root = std::sqrt(disc);
    const double t1 = -b - root, t2 = -b + root;
    const double z1 = ray.point.z + t1 * ray.direction.z, z2 = ray.point.z + t2 * ray.direction.z;
    const double t = std::abs(z1 - pupil_z_) <= std::abs(z2 - pupil_z_) ? t1 : t2;
    return ray.path + image_index_ * t;
}

std::vector<double> RayWavefront::opd_samples(double image_z, std::vector<size_t>* cells) const {
    const std::optional<double> axial = path_to_sphere(axial_, image_z);
    if (!axial) throw std::invalid_argument("the axial ray misses the reference sphere");
    std::vector<double> opd;
    opd.reserve(rays_.size());
    for (const TracedRay& ray : rays_) {
        const std::optional<double> path = path_to_sphere(ray, image_z);
        if (!path) continue;
        opd.push_back((*path - *axial) / wavelength_);
        if (cells) cells->push_back(ray.cell);
    }
    return opd;
}

PupilFunction RayWavefront::pupil(double image_z) const {
    PupilFunction p =
        make_pupil(sampling_, wavelength_, f_number_, [](double, double) { return 0.0; });
    std::fill(p.amplitude.begin(), p.amplitude.end(), 0.0);
    std::vector<size_t> cells;
    const std::vector<double> opd = opd_samples(image_z, &cells);
    for (size_t k = 0; k < opd.size(); ++k) {
        p.amplitude[cells[k]] = 1.0;
        p.opd_waves[cells[k]] = opd[k];
    }
    return p;
}

double RayWavefront::rms_waves(double image_z) const {
    const std::vector<double> opd = opd_samples(image_z, nullptr);
    double mean = 0;
    for (double w : opd) mean += w;
    mean /= static_cast<double>(opd.size());
    double variance = 0;
    for (double w : opd) variance += (w - mean) * (w - mean);
    return std::sqrt(variance / static_cast<double>(opd.size()));
}

double RayWavefront::best_focus_z() const {
    // The RMS wavefront is near-quadratic in the focus shift: golden-section search over the
    // rays' axis crossings widened by a few depths of focus (8 λF²).
    const double reach = focus_span_ + 8 * wavelength_ * f_number_ * f_number_;
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    double lo = paraxial_focus_z_ - reach, hi = paraxial_focus_z_ + reach;
    double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
    double fa = rms_waves(a), fb = rms_waves(b);
    for (int k = 0; k < 80 && hi - lo > 1e-9 * reach; ++k) {
        if (fa < fb) {
            hi = b, b = a, fb = fa;
            a = hi - golden * (hi - lo), fa = rms_waves(a);
        } else {
            lo = a, a = b, fa = fb;
            b = lo + golden * (hi - lo), fb = rms_waves(b);
        }
    }
    return 0.5 * (lo + hi);
}

}  // namespace lenslab
