#pragma once
// The Cooke triplet of the rayoptics documentation's "Triplet example" (M. J. Hayford,
// ray-optics, docs/source/examples/SasianTriplet/SasianTriplet.rst; attributed to Geiser,
// from J. Sasian's OPTI 517 Lens Design course): radii 23.713, 7331.288 / -24.456, 21.896 /
// 86.759, -20.4942; thicknesses 4.831 (N-LAK9), air 5.86, 0.975 (N-SF5), air 4.822, 3.127
// (N-LAK9), then air 41.2365 to the image. The stop is the front face of the flint (surface
// 3); the page uses an entrance pupil diameter of 12.5, a 20 degree field and 587.5618 nm.
// The diameters are the page's semi-diameters, rounded up; paraxial figures ignore them.

#include "analysis/aberrations/seidel.h"
#include "analysis/system/first_order.h"
#include "analysis/system/optical_system.h"
#include "lens_scene_builder.h"

namespace lenslab::test {

inline OpticalSystem sasian_triplet() {
    const double t1 = 4.831, a1 = 5.86, t2 = 0.975, a2 = 4.822, t3 = 3.127;
    return build_optical_system(lens_scene({
        {"L1", 0.0, t1, 20.02, sphere(23.713), sphere(7331.288), glass("N-LAK9")},
        {"L2", t1 + a1, t2, 9.6, sphere(-24.456), sphere(21.896), glass("N-SF5")},
        {"L3", t1 + a1 + t2 + a2, t3, 16.7, sphere(86.759), sphere(-20.4942), glass("N-LAK9")},
    }));
}

inline constexpr int kSasianStop = 2;  // surface 3, counted from 0
inline constexpr double kSasianEpd = 12.5, kSasianField = 20.0, kSasianNm = 587.5618;

// The page's stop, entrance pupil and wavelength, with the chief ray from `field` degrees.
inline FirstOrderOptions sasian_options(double field = kSasianField) {
    FirstOrderOptions o;
    o.wavelength_nm = kSasianNm;
    o.stop = kSasianStop;
    o.epd = kSasianEpd;
    o.fields = {field};
    return o;
}

// Where third order rules: a tenth of the page's entrance pupil and a 1 degree field, with
// the first-order data and the transverse Seidel aberrations (F and C lines) there.
inline constexpr double kSasianSmallField = 1.0;
struct SasianThirdOrder {
    FirstOrder first_order;
    SeidelTransverse transverse;
};
inline SasianThirdOrder sasian_third_order(const OpticalSystem& system) {
    FirstOrderOptions o = sasian_options(kSasianSmallField);
    o.epd = kSasianEpd / 10.0;
    const FirstOrder f = first_order(system, paraxial_trace(system, o.wavelength_nm), o);
    return {f, seidel_sums(system, f, kLineF, kLineC).transverse};
}

}  // namespace lenslab::test
