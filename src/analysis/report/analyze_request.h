#pragma once
// What the optical bench is asked of a scene's lenses (`lenslab analyze`, `lenslab sweep
// --analyze`, Python) and the answer: the figures, the figure files, and the JSON document
// `lenslab analyze --json` prints. One place, so every caller measures the same way.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/aberrations/field_curves.h"
#include "analysis/aberrations/field_map.h"
#include "analysis/aberrations/focal_shift.h"
#include "analysis/aberrations/ray_fans.h"
#include "analysis/aberrations/spot_diagrams.h"
#include "analysis/diffraction/diffraction_figures.h"
#include "analysis/diffraction/field_mtf.h"
#include "analysis/diffraction/field_psf.h"
#include "analysis/diffraction/wavefront_figures.h"
#include "analysis/report/lens_report.h"
#include "analysis/system/optical_system.h"
#include "optics/glass.h"
#include "scene/scene.h"
#include "util/error.h"

namespace lenslab {

struct AnalyzeRequest {
    double wavelength_nm = kLineD;
    // --wavelength was given: an imported lens file's wavelengths do not replace it.
    bool wavelength_given = false;
    std::vector<double> wavelengths;  // the primary is the middle one
    bool json = false;                // the command line's choice of output, JSON or a table
    std::string svg;
    double aperture = 0;  // beam diameter; 0: the usable aperture
    std::string lens;
    std::string unit;  // for the ray diagram's labels; empty: "units"
    // The aperture stop: a surface counted from 1, as lens design programs count; 0: the
    // lens file's stop (stop_position), else surface 1.
    int stop = 0;
    // A lens file's stop (lens_bench_defaults.h): its axial place from the first vertex and
    // its semi-diameter (0: not given). The surface there, or a stop in air inserted there.
    std::optional<double> stop_position;
    double stop_semi_diameter = 0;
    // --ray-aiming; none: the lens file's, else Real.
    std::optional<RayAiming> ray_aiming;
    double epd = 0, f_number = 0;
    double object_distance = 0;  // 0: the object at infinity
    std::vector<double> fields, field_heights;
    bool seidel = false;
    bool psf = false, mtf = false;
    // The wavefront at each field and wavelength (wavefront_figures.h).
    bool wavefront = false;
    int zernike_terms = 37;
    int wavefront_samples = 64;
    std::string wavefront_reference;      // "chief" (or empty) or "centroid": the sphere's centre
    std::vector<double> mtf_frequencies;  // empty: ten up to the cutoff
    // The MTF at this frequency through focus (cycles/mm; 0: none), over ± the half range (0:
    // one wave of defocus, 8 λN²) about the MTF's plane, at this many planes.
    double through_focus = 0, through_focus_range = 0;
    int through_focus_points = 11;
    bool spots = false;
    int rings = 6;                           // hexapolar rings of the spot diagrams
    std::optional<double> image_distance;    // image plane from the last vertex
    std::vector<double> wavelength_weights;  // one per wavelength; empty: equal
    bool fans = false;
    bool opd_fans = false;  // the OPD along the same lines of the stop (opd_fans.h)
    int fan_points = 21;
    // Figures; each implies its table.
    std::string spots_svg, fans_svg, curves_svg, focal_shift_svg, mtf_svg, opd_fans_svg;
    // False-colour PNG figures: the PSF of every field (implies psf; psf_log: its log scale)
    // and the OPD map of every field at the primary wavelength (implies wavefront).
    std::string psf_png, opd_png;
    bool psf_log = false;
    bool psf_huygens = false;  // the PSF of every field by Huygens' wavelets, not the transform
    bool field_curves = false;
    int field_curve_points = 11;
    bool focal_shift = false;
    // Field points along each side of the field map (RMS spot over x-y fields); 0: none.
    int field_map = 0;
    std::vector<double> band;  // the focal shift's; empty: the wavelengths' range, or F to C
    int focal_shift_points = 21;
    // The document's top-level keys wanted (empty: all): the lens report computes only what
    // they need (report_parts) and analyze_json writes only them.
    std::vector<std::string> report_keys;
};

// An option that does not fit the others or the system (a stop past the last surface, an
// unknown --lens): the command line's usage error, exit code 2 rather than 1.
class AnalyzeRequestError : public Error {
public:
    using Error::Error;
};

// The request with each figure file's table turned on (--spots-svg implies --spots, ...).
AnalyzeRequest with_implied_tables(AnalyzeRequest request);

// What the options of the figures say against each other, before any work: the message of
// the first conflict, if any.
std::optional<std::string> figure_option_error(const AnalyzeRequest& request);

struct AnalyzeResults {
    // What an imported lens file's bench data set (lens_bench_defaults.h), and what of it was
    // left out and why.
    std::vector<std::string> from_lens_file, not_from_lens_file;
    OpticalSystem system;
    LensReport report;
    std::optional<SpotDiagrams> spots;
    std::optional<RayFans> fans;
    std::optional<RayFans> opd_fans;  // in waves
    std::optional<DiffractionFigures> diffraction;
    std::optional<FieldMtfs> field_mtf;  // --mtf: every field, polychromatic
    std::optional<ThroughFocusMtf> through_focus;
    std::vector<FieldPsf> field_psf;  // --psf: every field, polychromatic
    std::optional<WavefrontFigures> wavefronts;
    std::optional<FieldCurves> curves;
    std::optional<FocalShift> shift;
    std::optional<FieldMap> field_map;
};

// Measures the scene's lenses as `request` asks (with_implied_tables applied) and writes the
// figure files it names. `scene_file` names the scene in messages ("" for none). Throws
// AnalyzeRequestError for options that do not fit, SceneError for a system it cannot measure.
AnalyzeResults analyze_scene(const Scene& scene, const AnalyzeRequest& request,
                             const std::string& scene_file);

// `lenslab analyze --json`'s document for results of analyze_scene, or only its keys in
// request.report_keys (unknown ones left out); "scene" is `scene_file`, left out when that
// is "".
nlohmann::ordered_json analyze_json(const AnalyzeResults& results, const AnalyzeRequest& request,
                                    const std::string& scene_file);
// The top-level keys of the whole document analyze_json would write, in order: what a
// message about an unknown report key lists.
std::vector<std::string> analyze_json_keys(const AnalyzeResults& results,
                                           const AnalyzeRequest& request,
                                           const std::string& scene_file);

// Both steps: the document `lenslab analyze SCENE_FILE --json ...` prints.
nlohmann::ordered_json analyze_report(const Scene& scene, const AnalyzeRequest& request,
                                      const std::string& scene_file = "");

}  // namespace lenslab
