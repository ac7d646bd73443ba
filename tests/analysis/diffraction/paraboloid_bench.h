#pragma once
// A paraboloid mirror (conic -1, vertex radius -2f) as a one-surface optical system, with the
// stop on it: perfect on its axis, with the coma and astigmatism of the closed forms off it.
// The diffraction tests' common bench.

#include <sstream>

#include "analysis/system/first_order.h"
#include "analysis/system/optical_system.h"
#include "analysis/system/paraxial.h"
#include "optics/glass.h"
#include "scene/scene_json.h"

namespace lenslab::test {

// Focal length `focal`, diameter `diameter` and a central hole of `hole` (0: none).
inline OpticalSystem paraboloid_mirror(double focal, double diameter, double hole = 0) {
    std::ostringstream s;
    s.precision(17);
    s << R"({"objects": [{"type": "lens_group", "name": "mirror", "vertex": [0, 0, 0],
        "axis": [0, 0, 1], "diameter": )"
      << diameter << R"(, "elements": [{"mirror": {"shape": "conic", "radius": )" << -2 * focal
      << R"(, "k": -1}, "diameter": )" << diameter << R"(, "hole_diameter": )" << hole
      << R"(, "gap": 100, "material": {"color": 0, "specular": 1}}]}]})";
    return build_optical_system(parse_scene(s.str(), "test", "", {.require_camera = false}));
}

// The stop on the mirror, an entrance pupil of `epd`, the d line, one field (degrees).
inline FirstOrder mirror_first_order(const OpticalSystem& system, double epd, double field) {
    FirstOrderOptions o;
    o.wavelength_nm = kLineD;
    o.stop = 0;
    o.epd = epd;
    o.fields = {field};
    return first_order(system, paraxial_trace(system, kLineD), o);
}

// The mirror and its first-order data at one field.
struct MirrorBench {
    OpticalSystem system;
    FirstOrder first;
};

inline MirrorBench mirror_bench(double focal, double diameter, double field) {
    MirrorBench b{paraboloid_mirror(focal, diameter), {}};
    b.first = mirror_first_order(b.system, diameter, field);
    return b;
}

}  // namespace lenslab::test
