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
#include "optics/spectrum.h"

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
    // The spread a broad spectrum (white light) is traced at when some transparent material
    // of the scene disperses; without dispersion such a light's rays are traced once, in
    // the middle one, and drawn in the light's own colour. A light with a line spectrum (a
    // laser) is traced at its line whatever this says.
    std::vector<double> wavelengths_nm{kLineF, kLineD, kLineC};
    std::optional<SectionBeam> beam;
    SpectrumPtr beam_spectrum;  // the beam's light; empty: D65 white
    int rays_per_light = 12;    // a fan around each light the plane cuts; 0: none
    int max_depth = 12;         // bounces followed along one path
    double min_weight = 0.01;   // fainter branches are not drawn
    double escape_length = 1;   // how far an escaping ray is drawn
};

// What a ray path met at one of its points after the first: the object, what the path's
// light did there (its own branch: refracted, reflected, totally reflected; or how it ended:
// absorbed, escaped), the surface's outward unit normal and the indices inside its solid and
// outside it.
struct SectionHit {
    int object = -1;  // -1: the ray escaped (the point is where its drawing stops)
    Event event = Event::Escape;
    Vec3 normal;
    double n_inside = 1, n_outside = 1;
};

// One polyline of a traced ray: a run of segments in world coordinates, the first starting
// where its branch left its parent path.
struct SectionRayPath {
    std::vector<Vec3> points;
    std::vector<SectionHit> hits;  // hits[k] is what happened at points[k + 1]
    double wavelength_nm = kLineD;
    double weight = 1;  // power fraction the branch starts with
    bool tir = false;   // the path continues after a total internal reflection
    // What it is drawn in: linear sRGB, brightest channel 1 (the wavelength's own colour, or
    // the light's where one path stands for its whole spectrum).
    Rgb colour{1, 1, 1};
    bool whole_spectrum = false;  // the path stands for all the light's wavelengths
    // A start ray's own path (along its strongest branches): the start ray's index among all
    // the view's start rays, so the same ray is found again after an edit; -1 for a branch.
    int start = -1;
};

// A wavelength a light's rays are traced at: its colour (linear sRGB, brightest channel 1)
// and the share of the light's power it is drawn with (1 for the strongest).
struct SectionWavelength {
    double nm = kLineD;
    double weight = 1;
    Rgb colour{1, 1, 1};
    bool whole_spectrum = false;
};

// The wavelengths a light of spectrum `s` is drawn in: the line of a line spectrum (95% of
// its power within 6 nm); else `spread` (the F, d and C lines), each weighted by the
// spectrum there, when `disperses`; else one path at the middle of `spread` in the
// spectrum's own colour.
std::vector<SectionWavelength> section_wavelengths(const Spectrum& s,
                                                   const std::vector<double>& spread,
                                                   bool disperses);

// The colour of light of one wavelength: its CIE 1931 chromaticity in linear sRGB, clipped
// to the gamut, brightest channel 1.
Rgb wavelength_rgb(double nm);

// The start rays of one light (or of the beam) with its spectrum.
struct SectionSource {
    std::vector<Ray> rays;
    SpectrumPtr spectrum;
};

// The start rays: the beam's, then a fan from each point light, spot (within its cone), beam
// and emitting sphere that the plane cuts, each with its light's spectrum.
std::vector<SectionSource> section_sources(const Scene& scene, const SectionPlane& plane,
                                           const SectionRayOptions& options);
// The same rays, one list.
std::vector<Ray> section_start_rays(const Scene& scene, const SectionPlane& plane,
                                    const SectionRayOptions& options);

// The polylines of one traced tree: the path of greatest weight continues through each
// hit, the other branches start new paths there.
void append_ray_paths(const RayTree& tree, const SectionWavelength& wavelength,
                      double escape_length, std::vector<SectionRayPath>& out);

// The beam a section view shows for `object`: for a lens whose axis lies in the plane,
// along its axis across 80% of its aperture, coming from the side of the scene's first
// light (or from its front); for such a mirror, onto its face along its axis; for any other object
// the plane cuts, along the plane's u across 80% of the height of its cross-section, from the -u
// side; nothing for -1, an object the plane misses, or one neither transparent nor specular (a
// screen).
std::optional<SectionBeam> default_section_beam(const Scene& scene, int object,
                                                const SectionPlane& plane, int rays = 15);

}  // namespace lenslab
