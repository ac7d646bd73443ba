#pragma once
// Interface of every intersectable solid or surface in a scene.

#include <optional>

#include "geometry/flat_patch.h"
#include "math/aabb.h"
#include "math/ray.h"

namespace lenslab {

struct SurfaceHit {
    double t = 0;
    Vec3 point;
    Vec3 normal;  // unit, geometric, pointing out of the solid (for a triangle: its face normal)
};

// A sphere holding every point of a shape: photons aimed at an object are sent into the
// cone this subtends (the tighter, the fewer aimed photons miss).
struct BoundingSphere {
    Vec3 centre;
    double radius = 0;
};

// The axis of symmetry of a lens or a mirror: a section view cuts the shape through it and
// sends its beam along it.
struct OpticalAxis {
    Vec3 centre;     // on the axis: a lens's middle, a mirror's vertex
    Vec3 direction;  // unit: a lens's axis; the way a mirror's face looks
    double diameter = 0;
    double thickness = 0;   // along the axis (0: a mirror)
    bool reflects = false;  // a mirror: light meets it travelling against `direction`
};

class Shape {
public:
    virtual ~Shape() = default;
    // Nearest intersection with t in (t_min, t_max); fills `hit` and returns true if found.
    virtual bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const = 0;
    virtual Aabb bounds() const = 0;
    // True when the shape encloses a volume, so refraction can enter and leave it.
    virtual bool is_closed() const = 0;
    // True for points inside (or on) a closed shape; always false for an open one. The
    // default asks which way the nearest surface along a fixed direction faces: a closed
    // shape's normals point out, so a ray from inside meets its surface leaving it.
    virtual bool contains(const Vec3& p) const;
    // Default: the sphere through the corners of bounds().
    virtual BoundingSphere bounding_sphere() const;
    // A flat shape's frame and outline (a disc, rectangle or triangle); nothing for others.
    virtual std::optional<FlatPatch> flat_patch() const { return std::nullopt; }
    // A lens's or mirror's axis; nothing for others.
    virtual std::optional<OpticalAxis> optical_axis() const { return std::nullopt; }
};

}  // namespace lenslab
