#pragma once
// Lens-only scenes for the optical-bench tests, written as scene JSON (no camera: the bench
// reads files that hold only lenses), so they go through the same reader as the command line.

#include <sstream>
#include <string>
#include <vector>

#include "scene/json_reader.h"
#include "scene/scene_json.h"

namespace lenslab::test {

// A surface: "flat", or a sphere of radius R (R = 0 means flat).
inline std::string sphere(double radius) {
    if (radius == 0) return R"({"shape": "flat"})";
    std::ostringstream s;
    s.precision(17);
    s << R"({"shape": "sphere", "radius": )" << radius << "}";
    return s.str();
}

// A lens object on the z axis: its front vertex at z_front, light along +z (or, with
// reversed, the same solid written with axis -z, back and front swapped).
struct LensSpec {
    std::string name;
    double z_front = 0, thickness = 1, diameter = 10;
    std::string front = sphere(0), back = sphere(0);
    std::string material = R"({"transparency": 1, "ior": 1.5})";
    double offset_x = 0;  // off the axis
    std::string axis = "[0, 0, 1]";
};

inline std::string lens_json(const LensSpec& l) {
    std::ostringstream s;
    s.precision(17);
    s << R"({"type": "lens", "name": ")" << l.name << R"(", "center": [)" << l.offset_x << ", 0, "
      << l.z_front + 0.5 * l.thickness << R"(], "axis": )" << l.axis << R"(, "thickness": )"
      << l.thickness << R"(, "diameter": )" << l.diameter << R"(, "front": )" << l.front
      << R"(, "back": )" << l.back << R"(, "material": )" << l.material << "}";
    return s.str();
}

// A scene holding the lenses and any extra objects (JSON), and no camera.
inline Scene lens_scene(const std::vector<LensSpec>& lenses,
                        const std::vector<std::string>& extra = {}) {
    std::string objects;
    for (const LensSpec& l : lenses) objects += (objects.empty() ? "" : ",\n") + lens_json(l);
    for (const std::string& e : extra) objects += (objects.empty() ? "" : ",\n") + e;
    return parse_scene(R"({"objects": [)" + objects + "]}", "test", "", {.require_camera = false});
}

inline std::string glass(const std::string& name) {
    return R"({"transparency": 1, "glass": ")" + name + R"("})";
}

}  // namespace lenslab::test
