#pragma once
// `lenslab analyze`: every figure the optical bench gives for a coaxial system, at one
// wavelength, gathered in one report that prints as a table or as JSON.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/aberrations/aberrations.h"
#include "analysis/aberrations/seidel.h"
#include "analysis/system/first_order.h"
#include "analysis/system/optical_system.h"
#include "analysis/system/paraxial.h"
#include "analysis/system/real_chief_ray.h"

namespace lenslab {

// What a report computes past the paraxial and first-order figures, which all else rests on.
// All of it by default; a caller that wants a few of the document's keys (report_parts) skips
// the rest, and those keys come out the same either way.
struct LensReportParts {
    bool beam = true;  // the collimated beam: rays, the best focus and its spot
    bool lsa = true;   // the longitudinal spherical aberration curve
    bool seidel = true;
    bool real_chief = true;
    bool paraxial_spot = true;  // the beam's spot at the paraxial focus (with `beam`)
};

struct LensReportOptions {
    double wavelength_nm = kLineD;  // the primary wavelength: the d line
    // Every wavelength asked for (the primary among them); with two or more, the chromatic
    // block and the Seidel colour sums use the shortest and longest, else the F and C lines.
    std::vector<double> wavelengths;
    double aperture_radius = 0;  // entrance beam radius; 0: the usable aperture
    // Stop, pupil, object and fields. Its wavelength is wavelength_nm. With neither an
    // entrance pupil diameter nor an F-number and the stop on the first surface (the
    // default), the entrance pupil is the axial beam (aperture_radius), as before stops.
    FirstOrderOptions first_order;
    int spot_rings = 16;  // hexapolar rings: 1 + 3 n (n + 1) rays
    int lsa_samples = 20;
    LensReportParts parts;
};

struct LensReport {
    double wavelength_nm = 0;
    ParaxialResult paraxial;  // at wavelength_nm
    std::vector<double> wavelengths;
    double short_nm = kLineF, long_nm = kLineC;  // the chromatic block's pair
    // At short_nm and long_nm (named for the default pair, the F and C lines).
    ParaxialResult paraxial_F, paraxial_C;
    double chromatic_shift_FC = 0;  // BFL(short) - BFL(long): paraxial longitudinal colour
    // Why the chromatic block (and the Seidel colour sums) could not be evaluated, "" when
    // it was: one wavelength asked for and a glass without data at the F or C line. Then
    // short_nm = long_nm = the wavelength asked for.
    std::string chromatic_unavailable;
    FirstOrder first_order;
    std::optional<RealChiefRay> real_chief;  // none when it cannot be traced
    Seidel seidel;
    double aperture_radius = 0;
    int rays = 0, rays_lost = 0;
    std::vector<LsaPoint> lsa;
    SpotDiagram spot_paraxial, spot_best;
    double best_focus = 0;  // best-focus plane, from the last vertex
};

// Throws SceneError when a wavelength lies outside a glass's range or the system is afocal.
LensReport analyze_lens_system(const OpticalSystem& system, const LensReportOptions& options);

// The report as JSON: every key, or only `keys` (in the document's order) when any are given;
// unknown keys are left out.
nlohmann::ordered_json report_json(const OpticalSystem& system, const LensReport& report,
                                   const std::vector<std::string>& keys = {});
// The top-level keys of report_json's whole document, in order.
std::vector<std::string> report_json_keys();
// What a report must compute for `keys` of its document (empty: all of it).
LensReportParts report_parts(const std::vector<std::string>& keys);
// With `seidel`, the table lists the Seidel sums surface by surface.
std::string report_table(const OpticalSystem& system, const LensReport& report,
                         bool seidel = false);

// "d line" for 587.56 nm and the like, or "" for a wavelength with no line name.
std::string fraunhofer_name(double nm);

}  // namespace lenslab
