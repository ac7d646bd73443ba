#include "optimize/merit_operand.h"

#include <algorithm>

#include "optimize/design_variable.h"
#include "optimize/lens_design_spec.h"
#include "optimize/model_glass.h"
#include "scene/json_reader.h"

namespace lenslab {

namespace {

bool mo_is_minimum(OperandKind kind) {
    return kind == OperandKind::MinCenterThickness || kind == OperandKind::MinEdgeThickness;
}

bool mo_real_ray(OperandKind kind) {
    return kind == OperandKind::RealRayX || kind == OperandKind::RealRayY;
}

// The operands measured at a field (one per design field when none is given).
bool mo_takes_field(OperandKind kind) {
    return kind == OperandKind::RmsSpot || kind == OperandKind::RmsWavefront ||
           kind == OperandKind::Mtf || kind == OperandKind::Distortion || mo_real_ray(kind);
}

}  // namespace

bool is_constraint(const MeritOperand& op) {
    return op.kind != OperandKind::Efl && op.kind != OperandKind::Bfl &&
           op.kind != OperandKind::EntrancePupilPosition &&
           op.kind != OperandKind::ExitPupilPosition && !mo_takes_field(op.kind);
}

std::string operand_label(const MeritOperand& op) {
    std::string label;
    for (const DesignEntryType<OperandKind>& t : operand_types()) {
        if (t.kind == op.kind) label = t.type;
    }
    if (op.kind == OperandKind::Mtf)
        label += " " + format_number(op.frequency) + " " +
                 (op.direction == "mean"         ? "T+S"
                  : op.direction == "tangential" ? "T"
                                                 : "S");
    if (mo_takes_field(op.kind)) label += " " + format_number(op.field) + "°";
    if (mo_real_ray(op.kind))
        label += " (" + format_number(op.px) + ", " + format_number(op.py) + ")";
    if (!op.lens.empty()) label += " " + op.lens;
    if (op.configuration >= 0) label += " [" + op.configuration_name + "]";
    return label;
}

double operand_residual(const MeritOperand& op, double value) {
    // The focal length through the power 1/EFL, which is nearly linear in the curvatures,
    // so a step from a weak start does not overshoot; scaled by target², it is EFL - target
    // to first order near the target (and so in the same unit).
    if (op.kind == OperandKind::Efl) return op.target * op.target * (1 / op.target - 1 / value);
    if (!is_constraint(op)) return value - op.target;
    if (mo_is_minimum(op.kind)) return std::max(0.0, op.target - value);
    return std::max(0.0, value - op.target);
}

std::vector<MeritOperand> read_merit_operands(const nlohmann::json& spec, const std::string& path,
                                              const nlohmann::ordered_json& scene,
                                              const std::vector<double>& fields) {
    JsonObjectReader reader(spec, path, entry_keys(operand_types()), "an operand");
    const DesignEntryType<OperandKind>& type =
        read_entry_type(spec, reader, operand_types(), "operand");
    MeritOperand op;
    op.path = path;
    op.kind = type.kind;
    op.weight = reader.number("weight", 1.0);
    if (!(op.weight >= 0)) {
        throw SceneError(reader.child_path("weight"),
                         "must be >= 0, got " + format_number(op.weight));
    }
    const bool needs_lens = std::count(type.keys.begin(), type.keys.end(), "lens") > 0;
    if (is_constraint(op)) {
        op.target = reader.number("limit");
    } else {
        // The spot's and the wavefront's natural target is none at all, the MTF's a perfect 1;
        // the focal length has no default.
        // The focal lengths and the pupils' positions have no natural target.
        const bool paraxial = op.kind == OperandKind::Efl || op.kind == OperandKind::Bfl ||
                              op.kind == OperandKind::EntrancePupilPosition ||
                              op.kind == OperandKind::ExitPupilPosition || mo_real_ray(op.kind);
        op.target = paraxial                      ? reader.number("target")
                    : op.kind == OperandKind::Mtf ? reader.number("target", 1.0)
                                                  : reader.number("target", 0.0);
    }
    if (op.kind == OperandKind::Mtf) {
        op.frequency = reader.number("frequency");
        if (!(op.frequency > 0)) {
            throw SceneError(
                reader.child_path("frequency"),
                "must be > 0 (cycles per unit length), got " + format_number(op.frequency));
        }
        op.direction = reader.choice("direction", "mean", {"tangential", "sagittal", "mean"});
    }
    if (mo_real_ray(op.kind)) {
        for (const char* key : {"px", "py"}) {
            const double v = reader.number(key, 0.0);
            if (!(std::abs(v) <= 1))
                throw SceneError(reader.child_path(key),
                                 "a normalised pupil coordinate, -1 to 1, got " + format_number(v));
            (std::string(key) == "px" ? op.px : op.py) = v;
        }
    }
    if (needs_lens) {
        op.lens = reader.string("lens");
        op.object = find_design_lens(scene, op.lens, reader.child_path("lens"));
        if (op.kind == OperandKind::GlassDistance && !is_model_glass(scene["objects"][op.object])) {
            throw SceneError(reader.child_path("lens"),
                             "the lens '" + op.lens +
                                 "' is not of a model glass (an inline \"ior\" of \"model\": "
                                 "\"abbe\"): it has no distance to the catalogue glasses");
        }
    }
    if (!mo_takes_field(op.kind)) return {op};
    // Distortion is a fraction of the image height: none on the axis.
    const bool off_axis_only = op.kind == OperandKind::Distortion;
    if (reader.has("field")) {
        op.field = reader.number("field");
        if (!(std::abs(op.field) < 90.0)) {
            throw SceneError(
                reader.child_path("field"),
                format_number(op.field) + " degrees is not a field angle (between -90 and 90)");
        }
        if (off_axis_only && op.field == 0) {
            throw SceneError(reader.child_path("field"),
                             "distortion is not defined on the axis (field 0): give a field "
                             "off it");
        }
        return {op};
    }
    std::vector<MeritOperand> each;
    for (double field : fields) {
        if (off_axis_only && field == 0) continue;
        op.field = field;
        each.push_back(op);
    }
    if (each.empty()) {
        throw SceneError(path,
                         "distortion needs a field off the axis, and the design's fields "
                         "are all 0");
    }
    return each;
}

}  // namespace lenslab
