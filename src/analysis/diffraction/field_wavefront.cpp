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

// A ray as it leaves the last surface, with the optical path it has run so far.
struct PathRay {
    Vec3 point, direction;
    double path = 0;
};

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

}  // namespace

FieldWavefront field_wavefront(const OpticalSystem& system, const FirstOrder& first_order,
                               const FieldWavefrontOptions& options) {
    if (system.has_grin()) {
        throw SceneError("objects",
                         "wavefront figures (OPD, Zernike, PSF, MTF) are not computed through "
                         "gradient-index lenses: the optical path along their curved rays is "
                         "not measured yet");
    }
    const double nm = options.wavelength_nm;
    const double wavelength = nm / options.nm_per_length_unit;
    FieldWavefront w;
    w.field = options.field;
    w.field_x = options.field_x;
    w.wavelength_nm = nm;
    w.image_z = options.image_z.value_or(system.last_vertex() + first_order.image_position);
    w.pupil = make_pupil(options.sampling, wavelength, first_order.working_f_number,
                         [](double, double) { return 0.0; });

    const bool collimated = !first_order.object_distance;
    const RayAimer aimer(system, first_order, options.field, nm, options.field_x);
    const auto path_of = [&](const RealRay& ray) -> std::optional<PathRay> {
        if (ray.fate != RayFate::Passed || !(ray.direction.z * system.image_travel() > 0))
            return std::nullopt;
        return path_ray(system, ray, nm, collimated);
    };
    const auto passed = [&](double px, double py) -> std::optional<PathRay> {
        const std::optional<RealRay> ray = aimer.trace(px, py);
        return ray ? path_of(*ray) : std::nullopt;
    };
    // The chief ray is a reference, not light: it may cross a central obstruction.
    const std::optional<Ray> chief_start = aimer.aim(0, 0);
    const std::optional<PathRay> chief =
        chief_start ? path_of(trace_real_ray(system, *chief_start, nm, Rims::Ignore))
                    : std::nullopt;
    if (!chief) throw std::invalid_argument("the chief ray does not pass the system");

    // The sphere: centred where the chief ray meets the image plane, through its crossing of
    // the exit pupil's plane.
    const auto along_chief_to = [&](double z) {
        return chief->point + chief->direction * ((z - chief->point.z) / chief->direction.z);
    };
    w.reference = along_chief_to(w.image_z);
    const double pupil_position = first_order.exit_pupil.position;
    const Vec3 pupil_point = std::isfinite(pupil_position)
                                 ? along_chief_to(system.last_vertex() + pupil_position)
                                 : chief->point;
    w.reference_radius = length(w.reference - pupil_point);
    if (!(w.reference_radius > 0))
        throw std::invalid_argument("the exit pupil lies in the image plane: no reference sphere");
    const double image_index = std::abs(system.n_after(system.surfaces.size() - 1, nm));
    w.image_index = image_index;
    // The optical path to the sphere, and where the ray meets it.
    const auto path_to_sphere = [&](const PathRay& ray) -> std::optional<std::pair<double, Vec3>> {
        const std::optional<double> t =
            distance_to_sphere(ray, w.reference, w.reference_radius, pupil_point);
        if (!t) return std::nullopt;
        return std::pair{ray.path + image_index * *t, ray.point + ray.direction * *t};
    };
    const auto chief_at_sphere = path_to_sphere(*chief);
    if (!chief_at_sphere) throw std::invalid_argument("the chief ray misses the reference sphere");
    const double chief_path = chief_at_sphere->first;

    PupilFunction& p = w.pupil;
    double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
    for (int i = 0; i < p.size; ++i)
        for (int j = 0; j < p.size; ++j) {
            const size_t cell = p.index(i, j);
            if (p.amplitude[cell] == 0) continue;
            p.amplitude[cell] = 0;
            const std::optional<PathRay> ray = passed(p.coordinate(j), p.coordinate(i));
            const auto at_sphere = ray ? path_to_sphere(*ray) : std::nullopt;
            if (!at_sphere) {
                ++w.lost;
                continue;
            }
            const double opd = (at_sphere->first - chief_path) / wavelength;
            w.sphere_points.push_back({cell, at_sphere->second});
            p.amplitude[cell] = 1;
            p.opd_waves[cell] = opd;
            lowest = std::min(lowest, opd);
            highest = std::max(highest, opd);
            ++w.passed;
        }
    if (w.passed == 0) throw std::invalid_argument("no ray of the beam passes the system");
    for (int i = 0; i + 1 < p.size; ++i)
        for (int j = 0; j + 1 < p.size; ++j) {
            const size_t cell = p.index(i, j);
            if (p.amplitude[cell] == 0) continue;
            for (const size_t next : {p.index(i, j + 1), p.index(i + 1, j)})
                if (p.amplitude[next] > 0)
                    w.max_step_waves =
                        std::max(w.max_step_waves, std::abs(p.opd_waves[next] - p.opd_waves[cell]));
        }
    w.rms_waves = wavefront_rms(p);
    w.pv_waves = highest - lowest;
    return w;
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
