#pragma once
// Interface of every intersectable solid or surface in a scene.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/flat_patch.h"
#include "math/aabb.h"
#include "math/ray.h"

namespace lenslab {

struct LensPrescription;
struct MirrorPrescription;

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
    // The prescription a lens or a mirror was built from, which the optical bench measures;
    // nothing for other shapes.
    virtual const LensPrescription* lens_prescription() const { return nullptr; }
    virtual const MirrorPrescription* mirror_prescription() const { return nullptr; }
    // The outline of a cut through the optical axis along unit `across` (square to the axis),
    // in the scene, as a closed curve: a lens's front face across its diameter in `steps`,
    // then its back face returning. Empty for shapes without one.
    virtual std::vector<Vec3> axial_outline(const Vec3& /*across*/, int /*steps*/) const {
        return {};
    }
    // For a surface a section view cuts facet by facet (a mesh's triangles, a mirror's face
    // as small quads): calls `visit` with each flat facet's corners. Nothing for others.
    using FacetVisitor = std::function<void(const Vec3* corners, int count)>;
    virtual void for_each_facet(const FacetVisitor& /*visit*/) const {}
    // An exact sphere's centre and radius (only spheres emit light); nothing for others.
    virtual std::optional<BoundingSphere> exact_sphere() const { return std::nullopt; }
    // Why a shape that could enclose a volume does not ("edge (4, 7) belongs to 1 face");
    // empty when it does or cannot.
    virtual std::string open_reason() const { return {}; }
};

}  // namespace lenslab
