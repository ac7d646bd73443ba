#pragma once
// One refracting surface of a lens, in its local frame: vertex at the origin, axis +z. Its
// shape is the sag z(x, y), the axial height above the vertex plane; for a surface of
// revolution it depends only on r = sqrt(x^2 + y^2). Kinds: flat, sphere, conic, asphere and
// a typed sag formula; each slots into LensSolid as its front or back face.

#include <limits>
#include <string>
#include <vector>

#include "math/ray.h"

namespace lenslab {

// What a lens knows about one face over the disc the face covers, measured once when the
// lens is built (`measure_span`). Numerical surfaces use it to bracket their roots: a ray
// can only meet the face inside the cylinder r <= semi_diameter and the slab
// z_min <= z <= z_max, and the face cannot rise faster than max_slope.
// The sag near the vertex as its Taylor series in r, to fourth order:
//   z(r) = curvature r^2 / 2 + a4 r^4 + O(r^6).
// a4 is the whole fourth-order coefficient: a sphere's curvature^3 / 8 is in it, so a
// conic's is (1 + k) c^3 / 8 and an even asphere's adds its A4. The optical bench's
// paraxial and third-order (Seidel) figures depend on a surface only through these two.
struct VertexSag {
    double curvature = 0;
    double a4 = 0;
};

struct SurfaceSpan {
    double semi_diameter = 0;
    double z_min = -std::numeric_limits<double>::infinity();
    double z_max = std::numeric_limits<double>::infinity();
    double max_slope = std::numeric_limits<double>::infinity();  // bound on |grad z|
};

class LensSurface;
// The vertex's Taylor coefficients of any surface of revolution, from its sag along +x: an
// interpolating polynomial in r^2 through eight points within a quarter of the
// semi-diameter (sag(0) = 0 required), whose first two coefficients are curvature / 2 and
// a4. For a sag that is itself a polynomial in r^2 of degree eight or less this is exact
// to rounding; for an analytic one the error falls geometrically with the degree.
VertexSag fit_vertex_sag(const LensSurface& surface, double semi_diameter);

class LensSurface {
public:
    virtual ~LensSurface() = default;

    // Axial height of the surface at radial distance r from the axis (for a surface that is
    // not one of revolution: along the local +x axis, i.e. sag_xy(r, 0)).
    virtual double sag(double r) const = 0;
    // Axial height at (x, y). Surfaces of revolution need not override it.
    virtual double sag_xy(double x, double y) const { return sag(std::hypot(x, y)); }
    // True when the sag depends on r alone; a lens then samples it along one radius only.
    virtual bool is_rotationally_symmetric() const { return true; }
    // The vertex's Taylor coefficients. The default reads them off the sag numerically
    // (fit_vertex_sag); the closed forms give them exactly. `semi_diameter` is the extent
    // the surface is used over, the scale of the numerical fit.
    virtual VertexSag vertex_sag(double semi_diameter) const {
        return fit_vertex_sag(*this, semi_diameter);
    }
    // Largest radial distance where the surface exists (a sphere of radius R: |R|).
    virtual double max_semi_diameter() const = 0;
    // Nearest crossing of `ray` (in the surface's local frame) with t in (t_min, t_max) and
    // radial distance at most span.semi_diameter (up to kSeamTolerance).
    virtual bool intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                           double& t) const = 0;
    // Whether intersect reads the span's z-range and slope bound (the numerical surfaces,
    // which bracket their roots with them) or its semi-diameter alone (the closed forms).
    virtual bool intersect_reads_bounds() const { return true; }
    // Unit normal at a point on the surface, with a positive z component.
    virtual Vec3 normal(const Vec3& p) const = 0;
    // Short human-readable form for messages, e.g. "sphere R=50".
    virtual std::string describe() const = 0;
    // Why the sag is not a finite number at (x, y), for messages ("sqrt of a negative
    // number"), or "" when the surface cannot say.
    virtual std::string why_undefined(double /*x*/, double /*y*/) const { return ""; }
};

// Radial distances within this relative margin of the semi-diameter still count as on the
// surface, so that a ray through the seam between a face and the rim cannot slip through.
inline constexpr double kSeamTolerance = 1e-9;

// Samples the sag over the disc of radius `semi_diameter` (along one radius for a surface
// of revolution, on a polar grid otherwise) and returns its padded z-range and slope bound.
// For a sag that is not finite somewhere on the disc the span is unbounded.
SurfaceSpan measure_span(const LensSurface& surface, double semi_diameter);

// The span `surface.intersect` needs over the disc: measure_span's for a numerical surface,
// the bare semi-diameter for a closed form (which reads nothing else), saving the sampling.
SurfaceSpan intersect_span(const LensSurface& surface, double semi_diameter);

// Points (x, y) on the disc of radius `semi_diameter` where a lens checks its faces: 513
// radii along +x when both faces are surfaces of revolution (`symmetric`), otherwise a polar
// grid of 129 radii by 128 angles. The rim (r = semi_diameter) is always included.
struct DiscPoint {
    double x, y;
};
std::vector<DiscPoint> disc_sample_points(double semi_diameter, bool symmetric);

}  // namespace lenslab
