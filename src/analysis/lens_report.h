#pragma once
// `lenslab analyze`: every figure the optical bench gives for a coaxial system, at one
// wavelength, gathered in one report that prints as a table or as JSON.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/aberrations.h"
#include "analysis/optical_system.h"
#include "analysis/paraxial.h"

namespace lenslab {

struct LensReportOptions {
    double wavelength_nm = kLineD;  // the d line
    double aperture_radius = 0;     // entrance beam radius; 0: the usable aperture
    int spot_rings = 16;            // hexapolar rings: 1 + 3 n (n + 1) rays
    int lsa_samples = 20;
};

struct LensReport {
    double wavelength_nm = 0;
    ParaxialResult paraxial;  // at wavelength_nm
    ParaxialResult paraxial_F, paraxial_C;
    double chromatic_shift_FC = 0;  // BFL(F) - BFL(C): paraxial longitudinal colour
    double aperture_radius = 0;
    int rays = 0, rays_lost = 0;
    std::vector<LsaPoint> lsa;
    SpotDiagram spot_paraxial, spot_best;
    double best_focus = 0;  // best-focus plane, from the last vertex
};

// Throws SceneError when a wavelength lies outside a glass's range or the system is afocal.
LensReport analyze_lens_system(const OpticalSystem& system, const LensReportOptions& options);

nlohmann::ordered_json report_json(const OpticalSystem& system, const LensReport& report);
std::string report_table(const OpticalSystem& system, const LensReport& report);

// "d line" for 587.56 nm and the like, or "" for a wavelength with no line name.
std::string fraunhofer_name(double nm);

}  // namespace lenslab
