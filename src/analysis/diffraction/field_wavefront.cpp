#include "analysis/diffraction/field_wavefront.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "analysis/system/ray_aiming.h"
#include "analysis/system/real_ray.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// The optical path from the object's wavefront to the ray's last point: segment k runs in the
// medium in front of surface k. For an object at infinity the rays start on a plane across
// the axis, not on the wavefront: each starts dot(start, d) further along the beam.
PathRay path_ray(const OpticalSystem& system, const RealRay& ray, double nm, bool collimated) {
    double path = 0;
    for (size_t k = 0; k + 1 < ray.points.size(); ++k)
        path += std::abs(system.n_before(k, nm)) * length(ray.points[k + 1] - ray.points[k]);
    if (collimated) {
        const Vec3 d = normalize(ray.points[1] - ray.points[0]);
        path += std::abs(system.n_before(0, nm)) * dot(ray.points[0], d);
    }
    return {ray.exit_point(), ray.direction, path};
}

// Distance along the ray to the reference sphere, at the crossing nearer `pupil` (the other
// lies beyond the image point); none when the ray misses the sphere.
std::optional<double> distance_to_sphere(const PathRay& ray, const Vec3& centre, double radius,
                                         const Vec3& pupil) {
    const Vec3 q = ray.point - centre;
    const double b = dot(q, ray.direction);
    const double c = dot(q, q) - radius * radius;
    const double disc = b * b - c;
    if (disc < 0) return std::nullopt;
    const double root = std::sqrt(disc);
    const double t1 = -b - root, t2 = -b + root;
    const double d1 = length(ray.point + ray.direction * t1 - pupil);
    const double d2 = length(ray.point + ray.direction * t2 - pupil);
    return d1 <= d2 ? t1 : t2;
}

// RMS (piston removed), peak-to-valley and the largest step between neighbours of the
// wavefront's passing samples.
void measure_spread(FieldWavefront& w) {
    const PupilFunction& p = w.pupil;
    double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
    w.max_step_waves = 0;
    for (int i = 0; i < p.size; ++i)
        for (int j = 0; j < p.size; ++j) {
            const size_t cell = p.index(i, j);
            if (p.amplitude[cell] == 0) continue;
            lowest = std::min(lowest, p.opd_waves[cell]);
            highest = std::max(highest, p.opd_waves[cell]);
            for (const size_t next :
                 {p.index(std::min(i + 1, p.size - 1), j), p.index(i, std::min(j + 1, p.size - 1))})
                if (next != cell && p.amplitude[next] > 0)
                    w.max_step_waves =
                        std::max(w.max_step_waves, std::abs(p.opd_waves[next] - p.opd_waves[cell]));
        }
    w.rms_waves = wavefront_rms(p);
    w.pv_waves = highest - lowest;
}

}  // namespace

FieldOpd::FieldOpd(const OpticalSystem& system, const FirstOrder& first_order,
                   const FieldWavefrontOptions& options)
    : system_(system),
      aimer_(system, first_order, options.field, options.wavelength_nm, options.field_x),
      nm_(options.wavelength_nm),
      wavelength_(options.wavelength_nm / options.nm_per_length_unit),
      collimated_(!first_order.object_distance) {
    if (system.has_grin()) {
        throw SceneError("objects",
                         "wavefront figures (OPD, Zernike, PSF, MTF) are not computed through "
                         "gradient-index lenses: the optical path along their curved rays is "
                         "not measured yet");
    }
    image_z_ = options.image_z.value_or(system.last_vertex() + first_order.image_position);
    // The chief ray is a reference, not light: it may cross a central obstruction.
    const std::optional<Ray> chief_start = aimer_.aim(0, 0);
    const std::optional<PathRay> chief =
        chief_start ? path_of(trace_real_ray(system, *chief_start, nm_, Rims::Ignore))
                    : std::nullopt;
    if (!chief) throw std::invalid_argument("the chief ray does not pass the system");

    // The sphere: centred where the chief ray meets the image plane, through its crossing of
    // the exit pupil's plane.
    const auto along_chief_to = [&](double z) {
        return chief->point + chief->direction * ((z - chief->point.z) / chief->direction.z);
    };
    reference_ = along_chief_to(image_z_);
    const double pupil_position = first_order.exit_pupil.position;
    pupil_point_ = std::isfinite(pupil_position)
                       ? along_chief_to(system.last_vertex() + pupil_position)
                       : chief->point;
    reference_radius_ = length(reference_ - pupil_point_);
    if (!(reference_radius_ > 0))
        throw std::invalid_argument("the exit pupil lies in the image plane: no reference sphere");
    image_index_ = std::abs(system.n_after(system.surfaces.size() - 1, nm_));
    const auto chief_at_sphere = path_to_sphere(*chief);
    if (!chief_at_sphere) throw std::invalid_argument("the chief ray misses the reference sphere");
    chief_path_ = chief_at_sphere->first;
}

std::optional<PathRay> FieldOpd::path_of(const RealRay& ray) const {
    if (ray.fate != RayFate::Passed || !(ray.direction.z * system_.image_travel() > 0))
        return std::nullopt;
    return path_ray(system_, ray, nm_, collimated_);
}

std::optional<std::pair<double, Vec3>> FieldOpd::path_to_sphere(const PathRay& ray) const {
    const std::optional<double> t =
        distance_to_sphere(ray, reference_, reference_radius_, pupil_point_);
    if (!t) return std::nullopt;
    return std::pair{ray.path + image_index_ * *t, ray.point + ray.direction * *t};
}

std::optional<double> FieldOpd::opd_waves(double px, double py, Vec3* at_sphere) const {
    const std::optional<RealRay> ray = aimer_.trace(px, py);
    const std::optional<PathRay> path = ray ? path_of(*ray) : std::nullopt;
    const auto at = path ? path_to_sphere(*path) : std::nullopt;
    if (!at) return std::nullopt;
    if (at_sphere) *at_sphere = at->second;
    return (at->first - chief_path_) / wavelength_;
}

FieldWavefront field_wavefront(const OpticalSystem& system, const FirstOrder& first_order,
                               const FieldWavefrontOptions& options) {
    const FieldOpd opd(system, first_order, options);
    FieldWavefront w;
    w.field = options.field;
    w.field_x = options.field_x;
    w.wavelength_nm = options.wavelength_nm;
    w.image_z = opd.image_z();
    w.reference = opd.reference();
    w.reference_radius = opd.reference_radius();
    w.image_index = opd.image_index();
    w.pupil = make_pupil(options.sampling, opd.wavelength(), first_order.working_f_number,
                         [](double, double) { return 0.0; });

    PupilFunction& p = w.pupil;
    for (int i = 0; i < p.size; ++i)
        for (int j = 0; j < p.size; ++j) {
            const size_t cell = p.index(i, j);
            if (p.amplitude[cell] == 0) continue;
            p.amplitude[cell] = 0;
            Vec3 at_sphere;
            const std::optional<double> waves =
                opd.opd_waves(p.coordinate(j), p.coordinate(i), &at_sphere);
            if (!waves) {
                ++w.lost;
                continue;
            }
            w.sphere_points.push_back({cell, at_sphere});
            p.amplitude[cell] = 1;
            p.opd_waves[cell] = *waves;
            ++w.passed;
        }
    if (w.passed == 0) throw std::invalid_argument("no ray of the beam passes the system");
    measure_spread(w);
    return w;
}

void refer_to_centroid(FieldWavefront& w) {
    const WavefrontTilt tilt = remove_tilt(w.pupil);
    const double scale = 2 * w.pupil.wavelength * w.pupil.f_number;
    w.reference.x += scale * tilt.x;
    w.reference.y += scale * tilt.y;
    measure_spread(w);
}

int samples_for_step(const FieldWavefront& wavefront, double step, int most) {
    const int now = wavefront.pupil.samples;
    if (!(wavefront.max_step_waves > step)) return now;
    const double wanted = std::ceil(now * wavefront.max_step_waves / step);
    const int even = 2 * static_cast<int>(std::ceil(std::min<double>(wanted, most) / 2));
    return std::max(now, std::min(even, most));
}

FieldWavefront resolved_field_wavefront(const OpticalSystem& system, const FirstOrder& first_order,
                                        FieldWavefrontOptions options) {
    FieldWavefront w = field_wavefront(system, first_order, options);
    const int needed = samples_for_step(w, kResolvedStepWaves, kMostResolvedSamples);
    if (needed <= options.sampling.samples) return w;
    options.sampling.samples = needed;
    return field_wavefront(system, first_order, options);
}

}  // namespace lenslab
