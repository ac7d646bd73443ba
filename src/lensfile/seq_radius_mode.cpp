#include "lensfile/seq_radius_mode.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "util/format_number.h"

namespace lenslab {

namespace {

// The semi-aperture surface j must have: its CIR, and for a lens seen from infinity, at the
// first curved surface and any flat ones before it, at least the entrance pupil's radius (the
// marginal ray runs parallel to the axis until it meets a curved surface, at that height).
double seq_required_semi_aperture(const LensFilePrescription& lens, size_t j) {
    const std::vector<LensFileSurface>& s = lens.surfaces;
    double sd = s[j].semi_diameter;
    bool parallel = std::isinf(s[0].thickness) && lens.aperture_type == "entrance_pupil_diameter";
    for (size_t k = 1; k < j && parallel; ++k) parallel = s[k].radius == 0.0;
    if (parallel) sd = std::max(sd, 0.5 * lens.aperture);
    return sd;
}

}  // namespace

std::string seq_implausible_radii(const LensFilePrescription& lens,
                                  const std::map<size_t, double>& unsure, bool as_curvatures) {
    const std::vector<LensFileSurface>& s = lens.surfaces;
    double thinnest = INFINITY;
    for (size_t j = 1; j + 1 < s.size(); ++j) {
        if ((!s[j].glass.empty() || s[j].model_nd > 0.0) && s[j].thickness > 0.0) {
            thinnest = std::min(thinnest, s[j].thickness);
        }
    }
    size_t curved = 0, tight = 0;
    for (const auto& [j, v] : unsure) {
        if (v == 0.0 || j == 0 || j + 1 >= s.size()) continue;
        const double r = std::abs(as_curvatures ? 1.0 / v : v);
        const double reach = 1.0 + s[j].conic > 0.0 ? r / std::sqrt(1.0 + s[j].conic) : INFINITY;
        const double sd = seq_required_semi_aperture(lens, j);
        if (sd > 0.0 && reach < sd) {
            return "surface " + std::to_string(j) + "'s " + format_number(v) +
                   " cannot reach its semi-aperture " + format_number(sd);
        }
        ++curved;
        if (r < 0.5 * thinnest) ++tight;
    }
    if (curved > 0 && tight == curved) {
        return "every face would be more curved than a hemisphere across the thinnest glass, " +
               format_number(thinnest) + " thick";
    }
    return "";
}

}  // namespace lenslab
