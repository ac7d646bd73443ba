#include "analysis/system/paraxial.h"

#include <cmath>

#include "analysis/system/grin_gap.h"
#include "util/scene_error.h"

namespace lenslab {

ParaxialResult paraxial_trace(const OpticalSystem& system, double nm) {
    // M = R_N T_{N-1} ... T_1 R_1 with refraction R = [[1, 0], [-φ, 1]], φ = c (n' - n),
    // and transfer T = [[1, t / n'], [0, 1]] across the gap t behind a surface (in a gradient
    // index, analysis/system/grin_gap.h).
    double a = 1, b = 0, c = 0, d = 1;
    const size_t count = system.surfaces.size();
    for (size_t i = 0; i < count; ++i) {
        const SystemSurface& s = system.surfaces[i];
        const double phi = s.curvature * (system.n_after(i, nm) - system.n_before(i, nm));
        c -= phi * a;
        d -= phi * b;
        if (i + 1 < count) {
            const GapTransfer t = gap_transfer(system, i, nm);
            const double a2 = t.a * a + t.b * c, b2 = t.a * b + t.b * d;
            c = t.c * a + t.d * c;
            d = t.c * b + t.d * d;
            a = a2;
            b = b2;
        }
    }
    ParaxialResult r;
    r.wavelength_nm = nm;
    r.a = a, r.b = b, r.c = c, r.d = d;
    r.power = -c;
    const double scale = system.scale();
    // A focal length a million times the system's size is, for a bench, no focus at all.
    // A system that is not rotationally symmetric is measured about its chief ray
    // (parabasal.h): as designed on the axis it may have no power in the y-z section (a
    // cylinder lens across it) and still focus.
    if (!(std::abs(r.power) * scale > 1e-6) && system.coaxial()) {
        throw SceneError("objects",
                         "the lens system is afocal (zero optical power): it has no focus");
    }
    const double n_object = system.n_before(0, nm);
    const double n_image = system.n_after(count - 1, nm);
    r.efl = 1.0 / r.power;
    // A ray parallel to the axis leaves at (A y, C y) and crosses it n' A / Φ behind the last
    // vertex; run backwards, one leaving parallel came from n D / Φ in front of the first.
    r.bfl = n_image * a / r.power;
    r.ffl = n_object * d / r.power;
    r.z_rear_focus = system.last_vertex() + r.bfl;
    r.z_front_focus = -r.ffl;
    r.z_rear_principal = r.z_rear_focus - n_image / r.power;
    r.z_front_principal = r.z_front_focus + n_object / r.power;
    return r;
}

}  // namespace lenslab
