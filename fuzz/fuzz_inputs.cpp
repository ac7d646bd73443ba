#include "fuzz_inputs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "math/formula.h"
#include "math/rng.h"
#include "render/camera.h"
#include "scene/interaction.h"
#include "scene/json_reader.h"
#include "scene/obj_reader.h"
#include "scene/scene_json.h"

namespace lenslab::fuzz {

namespace {

// The fuzzed formulas use at most three variables (x, y, z).
constexpr size_t kMaxVariablesUsed = 3;

// Follows a few camera rays through their first specular bounces: the intersection code of
// every shape the scene holds runs on the user's numbers.
void trace_some_rays(const Scene& scene) {
    const Camera camera(scene.camera, 8, 8);
    const double pixels[][2] = {{4, 4}, {0.5, 0.5}, {7.5, 0.5}, {0.5, 7.5}, {7.5, 7.5}};
    for (const auto& px : pixels) {
        Ray ray = camera.generate_ray(px[0], px[1]);
        for (int bounce = 0; bounce < 8; ++bounce) {
            Interaction it;
            if (!next_interaction(scene, ray, 550.0, it) || it.scattering.count == 0) break;
            ray = {it.point(), it.scattering.branches[bounce % it.scattering.count].direction};
        }
    }
}

// Points spelled by the bytes: 8 bytes a coordinate as a double, whatever its bits.
void append_spelled_points(std::string_view bytes, std::vector<Formula::Values>& points) {
    constexpr size_t kMostPoints = 16;  // enough to reach any branch; keeps each input quick
    constexpr size_t kBytesPerPoint = sizeof(double) * kMaxVariablesUsed;
    for (size_t at = 0; at + kBytesPerPoint <= bytes.size() && points.size() < kMostPoints;
         at += kBytesPerPoint) {
        Formula::Values p{};
        std::memcpy(p.data(), bytes.data() + at, kBytesPerPoint);
        points.push_back(p);
    }
}

// A few points from a stream seeded by the whole input, over many scales and both signs.
void append_drawn_points(std::string_view data, std::vector<Formula::Values>& points) {
    uint64_t seed = 14695981039346656037ull;  // FNV-1a
    for (const char c : data) seed = (seed ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    Rng rng(seed, 0);
    for (int i = 0; i < 4; ++i) {
        Formula::Values p{};
        for (size_t k = 0; k < kMaxVariablesUsed; ++k) {
            const double scale = std::ldexp(1.0, static_cast<int>(rng.uniform() * 80) - 40);
            p[k] = (2 * rng.uniform() - 1) * scale;
        }
        points.push_back(p);
    }
}

}  // namespace

void read_scene_input(std::string_view data, const std::string& base_dir) {
    Scene scene;
    try {
        scene = parse_scene(std::string(data), "fuzz", base_dir);
    } catch (const SceneError&) {
        return;  // refused with a message: what bad input must get
    }
    try {
        trace_some_rays(scene);
    } catch (const UndefinedFormulaError&) {
        return;  // a formula undefined between the reader's samples: also an error message
    }
}

void parse_formula_input(std::string_view data) {
    if (data.empty()) return;
    static const std::vector<std::string> kVariableSets[] = {
        {"r"}, {"x", "y", "r"}, {"x", "y", "z"}};
    const std::vector<std::string>& names = kVariableSets[static_cast<unsigned char>(data[0]) % 3];
    const std::string_view rest = data.substr(1);
    const size_t end = std::min(rest.find('\0'), rest.size());
    std::string text(rest.substr(0, end));
    try {
        const Formula f(text, names, "(fuzz)");
        std::vector<Formula::Values> points = {
            {0, 0, 0, 0}, {1, -2, 0.5, 0}, {-1e300, 1e-300, 3, 0}};
        append_spelled_points(rest.substr(std::min(end + 1, rest.size())), points);
        append_drawn_points(data, points);
        for (const Formula::Values& p : points) (void)f(p);
        for (const Formula::Values& p : points) (void)f.why_not_finite(p);
    } catch (const FormulaError&) {
        return;
    }
}

void read_obj_input(std::string_view data) {
    // Small limits, so that inputs of a few kilobytes reach them too.
    ObjLimits limits;
    limits.max_vertices = 64;
    limits.max_triangles = 64;
    limits.max_face_corners = 16;
    ObjMesh mesh;
    try {
        mesh = read_obj(data, "fuzz.obj", limits);
    } catch (const ObjError&) {
        return;
    }
    if (mesh.vertices.size() > limits.max_vertices) throw std::logic_error("too many vertices");
    for (const Vec3& v : mesh.vertices) {
        if (!is_finite(v) || std::abs(v.x) > limits.max_coordinate ||
            std::abs(v.y) > limits.max_coordinate || std::abs(v.z) > limits.max_coordinate) {
            throw std::logic_error("a vertex beyond the coordinate limit");
        }
    }
    size_t triangles = 0;
    size_t next = 0;
    for (const ObjFace& face : mesh.faces) {
        if (face.first != next || face.count < 3 || face.count > limits.max_face_corners ||
            face.first + face.count > mesh.corners.size()) {
            throw std::logic_error("a face outside the corner list or of the wrong size");
        }
        next += face.count;
        triangles += face.count - 2;
    }
    if (next != mesh.corners.size() || triangles > limits.max_triangles) {
        throw std::logic_error("corners left over, or too many triangles");
    }
    for (const int32_t c : mesh.corners) {
        if (c < 0 || static_cast<size_t>(c) >= mesh.vertices.size()) {
            throw std::logic_error("a corner that is not a vertex");
        }
    }
}

}  // namespace lenslab::fuzz
