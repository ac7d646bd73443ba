#pragma once
// The full tree of paths one ray takes through a scene: every reflected and refracted
// branch, each carrying its Fresnel-weighted share of the ray's power. `lenslab trace`
// prints it; the optical-bench measurements are built on it.

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "scene/scattering.h"
#include "scene/scene.h"

namespace lenslab {

// One event: the light went from `from` to `to`, met `object`, did `event` there and left
// along `direction` carrying `weight` (fraction of the traced ray's power, after what glass
// with absorption data took on the way: RayTree::absorbed counts it). At a dielectric
// the ray splits: the reflected and the refracted branch are siblings with the same segment.
// The root is the start of the ray (event "start", from = to = origin).
struct RayTreeNode {
    Vec3 from;
    std::optional<Vec3> to;      // empty when the ray escapes
    int object = -1;             // -1 when nothing was hit
    std::optional<Event> event;  // empty for the root
    Vec3 direction;
    double weight = 0;
    bool truncated = false;  // max_depth reached: this branch was not followed further
    std::vector<RayTreeNode> children;
    // Through a GRIN solid: the curved path from `from` to `to`, the integrator's points
    // (printed as "path"); empty for a straight segment.
    std::vector<Vec3> path;
    int steps = 0;  // the integrator's steps along `path` (printed as "steps")
    // At a hit: the surface's outward unit normal at `to` and the indices inside its solid
    // and outside it at the traced wavelength (what Snell's law used there).
    Vec3 normal;
    double n_inside = 1, n_outside = 1;
};

struct RayTreeOptions {
    int max_depth = 16;               // specular bounces followed along any one path
    double min_weight = 1e-3;         // branches carrying less are dropped (counted as truncated)
    double wavelength_nm = 587.5618;  // wavelength traced, in air (default: the d line)
};

struct RayTree {
    RayTreeNode root;
    // Where the power went; the three add up to 1.
    double escaped = 0, absorbed = 0, truncated = 0;
};

RayTree trace_ray_tree(const Scene& scene, const Ray& ray, const RayTreeOptions& options);

// The angle between two directions in degrees, 0-180; of a direction to the line of a
// surface's normal, 0-90 (an angle of incidence or refraction).
double angle_between_deg(const Vec3& a, const Vec3& b);
double angle_to_normal_deg(const Vec3& d, const Vec3& normal);

// Keys keep the documented order (from, to, object, event, weight, direction, children); a
// node that met a surface also has, before its children, the surface's `normal`, the angles
// of the arriving and the leaving light to it (`incidence_deg`, `leaving_deg`) and the indices
// `n_inside` its solid and `n_outside`.
nlohmann::ordered_json to_json(const Scene& scene, const RayTree& tree);

}  // namespace lenslab
