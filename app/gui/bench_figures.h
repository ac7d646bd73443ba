#pragma once
// The optical bench's figures of one lens system for the editor's bench dock, computed with
// the library calls `lenslab analyze` makes (app/cli/analyze_command.cpp), with fewer rays:
// the dock recomputes them after every edit.

#include <optional>
#include <string>
#include <vector>

#include "analysis/aberrations/field_curves.h"
#include "analysis/aberrations/ray_fans.h"
#include "analysis/aberrations/spot_diagrams.h"
#include "analysis/diffraction/diffraction_figures.h"
#include "analysis/diffraction/field_mtf.h"
#include "analysis/diffraction/field_psf.h"
#include "analysis/diffraction/wavefront_figures.h"
#include "analysis/figures/ray_diagram.h"
#include "analysis/system/first_order.h"

namespace lenslab::gui {

struct BenchSettings {
    std::vector<double> fields{0.0};         // degrees, the object at infinity
    std::vector<double> wavelengths;         // nm; empty: F, d, C (the middle one is the primary)
    double epd = 0;                          // entrance pupil diameter; 0: the library's default
    int stop = 1;                            // surface, counted from 1 as the CLI's --stop
    RayAiming ray_aiming = RayAiming::Real;  // as the CLI's --ray-aiming
    int rings = 4;                           // the spot diagrams' hexapolar rings
    int fan_points = 15;
    int field_curve_points = 7;
    int pupil_samples = 64;  // across the pupil for the MTF (raised for strong aberrations)
    // The PSF and the wavefront cost more than the rest (about 0.4 s each for a triplet): only
    // while their tab is shown.
    bool psf = false, wavefront = false;
};

// What the dock shows; a figure is absent when its computation failed (its reason in
// `errors`).
struct BenchFigures {
    std::optional<SpotDiagrams> spots;
    std::optional<RayFans> fans;
    std::optional<FieldCurves> curves;
    std::optional<DiffractionFigures> diffraction;  // on the axis: its best focus
    std::optional<FieldMtfs> mtf;                   // every field, polychromatic, in that plane
    std::vector<FieldPsf> psfs;  // every field, polychromatic, in that plane (settings.psf)
    std::optional<WavefrontFigures> wavefronts;  // every field, the primary wavelength, there
    std::vector<std::string> errors;
};

// Throws lenslab::Error when the first-order block cannot be set up (a bad stop, say).
BenchFigures compute_bench_figures(const OpticalSystem& system, const BenchSettings& settings);

// "0, 10.5, 14" → {0, 10.5, 14} (util/number_list.h); none when a part is not a number.
std::optional<std::vector<double>> number_list(const std::string& text);
// {0, 10.5, 14} → "0, 10.5, 14": what number_list reads back (10 significant digits).
std::string number_list_text(const std::vector<double>& values);

}  // namespace lenslab::gui
