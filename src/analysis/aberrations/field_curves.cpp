#include "analysis/aberrations/field_curves.h"

#include <cmath>

#include "analysis/system/field_beam.h"
#include "analysis/system/ray_aiming.h"

namespace lenslab {

namespace {

constexpr double kDegree = M_PI / 180.0;

// Where two rays, symmetric about the chief ray, meet along one transverse coordinate
// (`y`: meridional, else sagittal): z from the plane z_image.
double crossing(const std::optional<ExitRay>& a, const std::optional<ExitRay>& b, double z_image,
                bool y) {
    if (!a || !b) return NAN;
    const Vec3 pa = at_plane(a->point, a->direction, z_image);
    const Vec3 pb = at_plane(b->point, b->direction, z_image);
    const double ma = (y ? a->direction.y : a->direction.x) / a->direction.z;
    const double mb = (y ? b->direction.y : b->direction.x) / b->direction.z;
    const double qa = y ? pa.y : pa.x, qb = y ? pb.y : pb.x;
    return (qb - qa) / (ma - mb);
}

}  // namespace

double paraxial_chief_height(const OpticalSystem& system, const FirstOrder& f, double field,
                             double z) {
    if (f.field == 0) return NAN;
    const double ratio = f.object_distance
                             ? field / f.field
                             : std::tan(field * kDegree) / std::tan(f.field * kDegree);
    return ratio * f.chief.height_after(system, z);
}

FieldCurves field_curves(const OpticalSystem& system, const FirstOrder& first_order,
                         const FieldCurveOptions& options) {
    FieldCurves r;
    r.image_z = options.image_z.value_or(system.last_vertex() + first_order.image_position);
    const std::vector<double> wavelengths = options.wavelengths.empty()
                                                ? std::vector<double>{first_order.wavelength_nm}
                                                : options.wavelengths;
    // On the axis alone there is one field to show.
    const int n = options.max_field > 0 ? std::max(options.points, 1) : 1;
    const double d = kFieldCurveDifferentialPupil;
    for (double nm : wavelengths) {
        FieldCurve curve;
        curve.wavelength_nm = nm;
        for (int i = 0; i < n; ++i) {
            FieldCurvePoint p;
            p.field = n == 1 ? options.max_field : options.max_field * i / (n - 1);
            const RayAimer aimer(system, first_order, p.field, nm);
            const auto ray = [&](double px, double py) {
                return passed_exit_ray(system, aimer.trace(px, py));
            };
            p.tangential = crossing(ray(0, d), ray(0, -d), r.image_z, true);
            p.sagittal = crossing(ray(d, 0), ray(-d, 0), r.image_z, false);
            if (const auto chief = ray(0, 0)) {
                p.chief_height = at_plane(chief->point, chief->direction, r.image_z).y;
            }
            p.paraxial_height = paraxial_chief_height(system, first_order, p.field, r.image_z);
            if (p.field != 0)
                p.distortion = (p.chief_height - p.paraxial_height) / p.paraxial_height;
            curve.points.push_back(p);
        }
        r.curves.push_back(std::move(curve));
    }
    return r;
}

}  // namespace lenslab
