#pragma once
// Rays of a section view: start rays lying in the section plane (a beam of parallel rays,
// and fans from the lights the plane cuts), each traced non-sequentially through the whole
// scene by trace_ray_tree (the tracer of `lenslab trace`: every reflected, refracted and
// totally reflected branch with its Fresnel weight), flattened into polylines.
//
// Rays stay in the plane while the surfaces they meet are cut through their normals (a lens
// through its axis); a ray refracted out of the plane is drawn as its projection.

#include <optional>
#include <vector>

#include "analysis/section/section_plane.h"
#include "analysis/trace/ray_tree.h"
#include "optics/glass.h"

namespace lenslab {

// Parallel rays, evenly across `width`, leaving the line through `origin` perpendicular
// to `direction`. In world coordinates; the direction must lie in the plane.
struct SectionBeam {
    Vec3 origin;
    Vec3 direction;  // unit
    double width = 0;
    int rays = 15;
};

struct SectionRayOptions {
    // Each start ray is traced at each; only at the middle one when no transparent material
    // of the scene disperses (the paths would coincide).
    std::vector<double> wavelengths_nm{kLineF, kLineD, kLineC};
    std::optional<SectionBeam> beam;
    int rays_per_light = 12;   // a fan around each light the plane cuts; 0: none
    int max_depth = 12;        // bounces followed along one path
    double min_weight = 0.01;  // fainter branches are not drawn
    double escape_length = 1;  // how far an escaping ray is drawn
};

// One polyline of a traced ray: a run of segments in world coordinates, the first starting
// where its branch left its parent path.
struct SectionRayPath {
    std::vector<Vec3> points;
    double wavelength_nm = kLineD;
    double weight = 1;  // power fraction the branch starts with
    bool tir = false;   // the path continues after a total internal reflection
};

// The start rays: the beam's, then a fan from each point light, spot (within its cone), beam
// and emitting sphere that the plane cuts.
std::vector<Ray> section_start_rays(const Scene& scene, const SectionPlane& plane,
                                    const SectionRayOptions& options);

// The polylines of one traced tree: the path of greatest weight continues through each
// hit, the other branches start new paths there.
void append_ray_paths(const RayTree& tree, double wavelength_nm, double escape_length,
                      std::vector<SectionRayPath>& out);

// The beam a section view shows for `object`: for a lens whose axis lies in the plane,
// along its axis across 80% of its aperture, coming from the side of the scene's first
// light (or from its front); for any other object the plane cuts, along the plane's u
// across 80% of the height of its cross-section, from the -u side; nothing for -1 or an
// object the plane misses.
std::optional<SectionBeam> default_section_beam(const Scene& scene, int object,
                                                const SectionPlane& plane, int rays = 15);

}  // namespace lenslab
