#pragma once
// The variables of an optimisation (docs/optimizer.md): numbers of a lens scene the optimiser
// may change, each read from and written into the scene's JSON, so the optimised design is
// the same scene file with new numbers. A face's curvature c = 1/R (not R, so a flat face
// can bend either way through c = 0), its conic constant and aspheric coefficients, a lens's
// centre thickness, the air gap after a lens (moving every lens behind it), and the distance
// from the last vertex to the image plane, a model glass's n_d and V_d (a lens whose
// material is written inline with an `ior` of `"model": "abbe"`), a lens's decentre and tilt
// from its designed axis, and a catalogue glass's melt departure (tolerancing's errors).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

enum class VariableKind {
    Curvature,
    Conic,
    Aspheric,
    Thickness,
    AirGap,
    ImageDistance,
    GlassIndex,  // n_d of a model glass
    GlassAbbe,   // V_d of a model glass
    // A lens moved from its designed axis (its decenter_x, ... keys; mm and degrees).
    DecenterX,
    DecenterY,
    TiltX,
    TiltY,
    // A catalogue glass's melt: its material's delta_n_d and delta_V_d.
    MeltIndex,
    MeltAbbe,
};

struct DesignVariable {
    VariableKind kind = VariableKind::Curvature;
    int object = -1;           // index into the scene JSON's `objects` (none for the image)
    std::string lens;          // as the design names it
    std::string surface;       // "front" or "back": curvature, conic, aspheric
    int order = 0;             // aspheric: the power of r, 4, 6, ... 16
    double semi_diameter = 0;  // the lens's, for the finite-difference step
    std::string path;          // "variables[2]", for messages
    // Bounds the optimiser keeps the variable within (optimize/variable_bounds.h), both or
    // neither; they are also the region the global search draws its starts from.
    std::optional<double> min, max;
    // A multi-configuration design's variable of one configuration (an air gap, the image
    // distance); -1: one value shared by every configuration.
    int configuration = -1;
    std::string configuration_name;

    bool bounded() const { return min.has_value(); }
    // n_d or V_d: a model glass's, which glass substitution replaces by a catalogue glass.
    bool of_glass() const {
        return kind == VariableKind::GlassIndex || kind == VariableKind::GlassAbbe;
    }
    bool of_melt() const {
        return kind == VariableKind::MeltIndex || kind == VariableKind::MeltAbbe;
    }
    bool of_pose() const {
        return kind == VariableKind::DecenterX || kind == VariableKind::DecenterY ||
               kind == VariableKind::TiltX || kind == VariableKind::TiltY;
    }
};

// The design as the optimiser changes it: the scene and the image plane behind it.
struct DesignState {
    nlohmann::ordered_json scene;
    double image_distance = 0;  // from the last vertex; used when the image is not paraxial
};

// "curvature crown.front", "air_gap crown", "image_distance".
std::string variable_label(const DesignVariable& v);

double variable_value(const DesignState& state, const DesignVariable& v);
// Writes `value` in. A curvature of 0 makes a sphere "flat" (and a flat face a sphere
// when it bends); a thickness keeps the front vertex where it is and moves every lens
// behind, as an air gap does.
void set_variable(DesignState& state, const DesignVariable& v, double value);

// The finite-difference step: what changes the sag at the lens's rim by about 1e-5 (the
// scene's unit, mm for lens prescriptions), 1e-5 of a length.
double variable_step(const DesignVariable& v);

// Reads `variables[i]` of a design against its scene: the lens must be a prescription `lens`
// object named by its `name` or "objects[i]", its face of the kind the variable needs.
// Throws SceneError naming the JSON path.
DesignVariable read_design_variable(const nlohmann::json& spec, const std::string& path,
                                    const nlohmann::ordered_json& scene);

// The material of lens `object` of a scene JSON, a named one looked up; none if it has none.
const nlohmann::ordered_json* lens_material(const nlohmann::ordered_json& scene, int object);

// A prescription lens object (`lens` with `thickness`) of a scene JSON: its index in
// `objects` and the name a design gives it (its `name`, else "objects[i]").
struct DesignLens {
    int object = -1;
    std::string name;
};
std::vector<DesignLens> design_lenses(const nlohmann::ordered_json& scene);

// The index of the lens object `name` names in the scene JSON (its `name`, or "objects[i]"),
// a prescription lens (with `thickness`); throws SceneError at `path` naming the lenses
// there are.
int find_design_lens(const nlohmann::ordered_json& scene, const std::string& name,
                     const std::string& path);

}  // namespace lenslab
