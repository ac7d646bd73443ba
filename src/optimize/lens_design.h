#pragma once
// The design file of `lenslab optimize` (docs/optimizer.md): the lens system to optimise
// (a scene file or a scene inline), how it is used (aperture stop, entrance pupil, fields,
// wavelengths and their weights, the image plane), what may change (variables) and what is
// wanted (operands of the merit function).

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/system/first_order.h"
#include "optimize/design_variable.h"
#include "optimize/glass_choice.h"
#include "optimize/merit_operand.h"

namespace lenslab {

// The design file's `tolerances` block (`lenslab tolerance`, optimize/tolerance.h): ± errors
// in mm applied to every lens of the system, and the Monte Carlo's size.
struct ToleranceSettings {
    double radius = 0;     // of every curved face's radius
    double thickness = 0;  // of every lens's centre thickness
    double air_gap = 0;    // of every air gap between lenses
    double decenter = 0;   // of every lens across its axis, in x and in y
    double tilt = 0;       // degrees, of every lens about its front vertex, in x and in y
    double index = 0;      // of every catalogue glass's n_d
    double abbe = 0;       // percent of every catalogue glass's V_d
    int trials = 1000;
    uint64_t seed = 1;
    bool refocus = true;  // the back focus as compensator
    // What a made lens is judged by, per field: "rms_spot" (mm), "rms_wavefront" (waves) or
    // "mtf" at `frequency` (cycles/mm, the mean of tangential and sagittal).
    std::string criterion = "rms_spot";
    double frequency = 0;
};

// The design file's `global_search` block (`lenslab optimize`, optimize/global_search.h).
struct GlobalSearchSettings {
    int starts = 0;  // 0: no global search
    int start_iterations = 15;
    int keep = 3;  // the best starts polished with the design's whole iteration count
    uint64_t seed = 1;
};

// The design file's `glass_substitution` block (optimize/model_glass.h): every lens of a model
// glass given, after the optimisation, the best of the catalogue glasses nearest to it.
struct GlassSubstitutionSettings {
    bool enabled = false;             // whether the design has the block
    std::vector<std::string> makers;  // empty: every maker's catalogue
    int candidates = 5;
};

// One configuration of a multi-configuration design (a zoom's focal length, say): the air
// gaps it sets, its fields and its image plane. Its operands and variables are among the
// design's, marked with its index.
struct DesignConfiguration {
    std::string name;
    std::vector<double> fields;
    std::optional<double> image_distance;
    // Air gaps it sets (air_gap variables with the value they take in it).
    std::vector<std::pair<DesignVariable, double>> air_gaps;
};

struct LensDesign {
    std::string system_file;       // the scene file, relative to the working folder; "" inline
    std::string base_dir;          // the folder relative paths of the scene resolve against
    nlohmann::ordered_json scene;  // the starting system, keys in the file's order
    int stop = 0;                  // the aperture stop, a surface index (0-based)
    // Instead: a stop in the air `distance` behind the back vertex of the lens `object` (an
    // index into the scene JSON's objects), put there at every evaluation.
    struct AirStop {
        int object = -1;
        std::string lens;
        double distance = 0;
    };
    std::optional<AirStop> stop_in_air;
    double epd = 0, f_number = 0;              // one of the two
    std::vector<double> fields;                // degrees, the object at infinity
    std::vector<double> wavelengths, weights;  // nm; the primary is the middle one
    int rings = 4;                             // of the hexapolar grid of each spot
    RayAiming ray_aiming = RayAiming::Real;    // how the spots' rays find the stop
    // The image plane's distance from the last vertex; none: the paraxial focus of the
    // primary wavelength, solved at every step.
    std::optional<double> image_distance;
    std::vector<DesignVariable> variables;
    std::vector<MeritOperand> operands;
    int iterations = 100;
    // Glass choice after the continuous optimisation, each glass re-optimised this long.
    std::vector<GlassChoice> glass_choices;
    int glass_iterations = 20;
    ToleranceSettings tolerances;
    GlobalSearchSettings global_search;
    GlassSubstitutionSettings glass_substitution;
    // None: one configuration, the design's own. Otherwise the operands are every
    // configuration's (the shared ones read once per configuration), the variables shared or
    // of one configuration, and the scene, fields and image_distance are configuration 0's
    // starting point that each configuration changes.
    std::vector<DesignConfiguration> configurations;

    double primary_wavelength() const { return wavelengths[(wavelengths.size() - 1) / 2]; }
};

// Reads a design file; the system's scene file is found relative to it. Throws SceneError
// naming the file and the JSON path.
LensDesign load_lens_design(const std::string& path);

// A design from parsed JSON; `base_dir` is the design file's folder ("" = the working one).
// Throws SceneError naming the JSON path.
LensDesign lens_design_from_json(const nlohmann::json& root, const std::string& base_dir);

}  // namespace lenslab
