#pragma once
// A coaxial lens system read off a scene: the lens objects that share one optical axis,
// ordered along it, as the sequence of refracting surfaces a beam meets, with the medium on
// each side. Two lenses whose facing surfaces coincide (same shape at the same place: a
// cemented doublet) meet at one glass-to-glass interface. A lens group holding mirrors is a
// folded system: its elements in the group's order, the light turning back along the axis
// at each mirror. Everything the optical bench measures (paraxial.h, real_ray.h,
// aberrations.h) works on this model.
//
// System coordinates: z along the axis in the direction light enters, 0 at the first
// vertex; (x, y) across it in the frame `frame` (y is the meridional direction of the
// diagrams). Lengths are in the scene's unit (millimetres for lens prescriptions).
//
// Behind an odd number of mirrors light travels towards -z. The paraxial traces then use
// the signed index convention of Zemax and CODE V (Welford, Aberrations of Optical Systems,
// section 2.3): n_before / n_after carry the sign of the direction of travel, so a mirror is
// a surface with n' = -n, distances stay in system z and slopes are dy/dz; the formulas for
// refracting systems then hold unchanged.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/lens/lens_surface.h"
#include "geometry/shape.h"
#include "math/frame.h"
#include "optics/glass.h"
#include "optics/grin_profile.h"
#include "scene/scene.h"

namespace lenslab {

// Where a decentred or tilted surface stands (a lens group element's decentre and tilts): its
// vertex and its own axes (w: the axis its sag is measured along) in system coordinates.
struct SurfacePose {
    Vec3 vertex;
    Frame axes;
};

// One refracting interface or mirror of the system.
struct SystemSurface {
    std::shared_ptr<const LensSurface> shape;
    double orientation = 1.0;  // +1: the shape's local +z is the system's +z; -1: reversed
    double z = 0.0;            // axial position of the vertex
    double travel = 1.0;       // +1: light arrives travelling towards +z; -1: towards -z
    bool mirror = false;       // reflects (the medium is the same on both sides)
    double semi_diameter = 0.0;
    double hole_semi_diameter = 0.0;  // a mirror's central hole: light nearer the axis passes
                                      // it by and is lost to the sequence
    SurfaceSpan span;  // intersect_span over `semi_diameter` (bounds for the numerical surfaces)
    // Measured over twice the semi-diameter (within the shape's own limit): ray aiming traces
    // past the rims, as Zemax's does, so a stop point outside a lens's clear aperture can
    // still be aimed at and that lens then reported as vignetting the ray.
    SurfaceSpan aim_span;
    double curvature = 0.0;   // paraxial vertex curvature in system z (> 0: centre at +z)
    double a4 = 0.0;          // the sag's r^4 coefficient in system z (geometry VertexSag)
    int element_before = -1;  // index into OpticalSystem::elements; -1: the outside (air)
    int element_after = -1;
    std::string label;  // "objects[0].front", "objects[0].back = objects[1].front"
    // A surface off the axis or tilted from it; none: its vertex at (0, 0, z), its own z along
    // `orientation`. `z`, `curvature` and `a4` then describe it as designed, on the axis: the
    // system's paraxial figures (nominal pupils) use them, real rays the pose.
    std::optional<SurfacePose> pose;

    bool cemented() const { return element_before >= 0 && element_after >= 0; }
    // The direction of travel behind the surface.
    double travel_after() const { return mirror ? -travel : travel; }
    // A ray (system coordinates) in the surface's own frame: vertex at the origin, the sag
    // along +z.
    Ray to_local(const Vec3& p, const Vec3& d) const {
        if (pose) return {pose->axes.to_local(p - pose->vertex), pose->axes.to_local(d)};
        return {{p.x, p.y, orientation * (p.z - z)}, {d.x, d.y, orientation * d.z}};
    }
    // A direction of the surface's own frame (its normal) in system coordinates.
    Vec3 to_system(const Vec3& local) const {
        if (pose) return pose->axes.to_world(local);
        return {local.x, local.y, orientation * local.z};
    }
    // Whether a point of the surface (system coordinates) lies in a mirror's central hole.
    bool in_hole(const Vec3& p) const {
        const Vec3 q = pose ? pose->axes.to_local(p - pose->vertex) : p;
        return q.x * q.x + q.y * q.y < hole_semi_diameter * hole_semi_diameter;
    }
    // Axial position of the surface at distance r from the axis.
    double z_at(double r) const { return z + orientation * shape->sag(r); }
};

// One lens object of the system.
struct SystemElement {
    int object = -1;    // index into Scene::objects
    std::string path;   // "objects[3]"
    std::string name;   // the object's name (its path when it has none)
    std::string glass;  // catalogue name, else the index model ("constant n = 1.5")
    IndexModelPtr index;
    int first_surface = 0;  // the surfaces light meets entering and leaving it
    int last_surface = 0;
    double semi_diameter = 0.0;
    // A gradient index about the system's axis (radial or axial, optics/grin_profile.h),
    // null for homogeneous glass; its centre in world coordinates; and the lens solid, in
    // which rays curve from one face to the other (analysis/system/grin_gap.h).
    std::shared_ptr<const GrinProfile> grin;
    Vec3 grin_centre;
    std::shared_ptr<const Shape> solid;
};

struct OpticalSystem {
    Vec3 origin;  // world position of the first vertex
    Frame frame;  // w: the axis, the way light travels
    std::vector<SystemSurface> surfaces;
    std::vector<SystemElement> elements;
    // Objects left out: not lenses, or lenses off the axis of the lens asked for.
    std::vector<std::string> ignored;

    double last_vertex() const { return surfaces.back().z; }
    // The direction of travel in image space (+1: towards +z).
    double image_travel() const { return surfaces.back().travel_after(); }
    bool folded() const;  // holds a mirror
    // No surface decentred or tilted: rotationally symmetric about the axis (paraxial
    // figures and Seidel sums hold); else first-order figures are parabasal.
    bool coaxial() const;
    // The system's size: its length along the axis or its largest diameter.
    double scale() const;
    // Refractive index of the medium in front of / behind surface i at a wavelength (in air),
    // at the surface's vertex (where a gradient index is, on the axis), signed by the
    // direction of travel there (negative behind an odd number of mirrors).
    double n_before(size_t i, double nm) const;
    double n_after(size_t i, double nm) const;
    // Index of element `element` (-1: the outside) at point p (system coordinates), unsigned.
    double index_at(int element, const Vec3& p, double nm) const;
    bool has_grin() const;
    // Largest semi-diameter of any element or mirror: the scale of the system across the axis.
    double max_semi_diameter() const;

    Vec3 to_world(const Vec3& p) const { return origin + frame.to_world(p); }
    Vec3 direction_to_world(const Vec3& d) const { return frame.to_world(d); }
    Vec3 to_system(const Vec3& world) const { return frame.to_local(world - origin); }
};

// Builds the system from every lens in `scene`; they must share one axis. When `lens` (an
// index into scene.objects) is given, from that lens and the lenses on its axis, leaving
// the others out. The axis points the way the chosen (or first) lens's `axis` does: light
// enters through its front face. A lens group holding a mirror is built alone, in its own
// order (the one `lens` belongs to, else the first such group), the other objects listed
// as ignored. Throws SceneError whose path names the offending object ("objects[3]"): no
// lens, lenses off the common axis, overlapping lenses, an opaque lens, a face that is not
// a surface of revolution, a gradient index not symmetric about the axis or in a folded
// system. (system_builder.cpp)
OpticalSystem build_optical_system(const Scene& scene, std::optional<int> lens = {});

// The surface whose vertex lies at axial position z (within 1e-9 of the system's length),
// if any; in a folded system, the first such.
std::optional<int> surface_at(const OpticalSystem& system, double z);

// Puts an aperture stop in air at axial position z: a flat surface of rim `semi_diameter`
// with air on both sides (labelled "stop"), which bends no ray and stops those outside its
// rim, where the light first crosses that plane in air (a folded system crosses a plane more
// than once). Returns its index. Throws SceneError when z lies inside a lens or the light
// never crosses it.
int insert_air_stop(OpticalSystem& system, double z, double semi_diameter);

// Refuses a wavelength outside a glass's published validity range; `what` names the
// figure it is for ("--wavelength"). Throws SceneError naming the lens.
void check_wavelength(const OpticalSystem& system, double nm, const std::string& what);

}  // namespace lenslab
