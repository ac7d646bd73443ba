#pragma once
// The operands of the merit function (docs/optimizer.md): figures of a design with a
// target and a weight, merit = sum of weight * residual². Targets: the paraxial focal
// length, back focal length and pupil positions, a field's distortion, the polychromatic RMS spot
// of a field, the RMS wavefront of a field and its MTF at a frequency, where a real ray meets
// the image plane. Constraints are one-sided:
// their residual is zero while the limit holds (centre and edge thickness of a lens, the total
// length).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lenslab {

enum class OperandKind {
    Efl,
    Bfl,
    EntrancePupilPosition,
    ExitPupilPosition,
    Distortion,
    RmsSpot,
    RmsWavefront,
    Mtf,
    MinCenterThickness,
    MaxCenterThickness,
    MinEdgeThickness,
    MaxTotalLength,
    GlassDistance,  // a model glass's distance on the glass map to the nearest catalogue glass
    RealRayX,       // where a real ray meets the image plane (Zemax REAX, REAY)
    RealRayY,
};

struct MeritOperand {
    OperandKind kind = OperandKind::Efl;
    double target = 0;  // the target, or a constraint's limit
    double weight = 1;
    double field = 0;       // rms_spot, rms_wavefront, mtf, distortion: the field in degrees
    double frequency = 0;   // mtf: cycles per unit length
    double px = 0, py = 0;  // real rays: the normalised pupil coordinates (-1 to 1)
    std::string direction;  // mtf: "tangential", "sagittal" or "mean" (of the two)
    int object = -1;        // thickness constraints: the lens's index in the scene JSON
    std::string lens;
    std::string path;  // "operands[1]"
    // A multi-configuration design's (lens_design.h): the configuration it is evaluated in.
    int configuration = -1;
    std::string configuration_name;
};

bool is_constraint(const MeritOperand& op);
// "efl", "rms_spot 14°", "mtf 40 T 14°", "min_edge_thickness crown".
std::string operand_label(const MeritOperand& op);
// value - target for a target (for the EFL, target² (1/target - 1/EFL): the difference in
// power in units of length, EFL - target near the target); for a constraint the amount by which
// `value` breaks the limit, 0 while it holds.
double operand_residual(const MeritOperand& op, double value);

// Reads `operands[i]`; an rms_spot, rms_wavefront or mtf without a field stands for one operand
// per design field.
// Throws SceneError naming the JSON path.
std::vector<MeritOperand> read_merit_operands(const nlohmann::json& spec, const std::string& path,
                                              const nlohmann::ordered_json& scene,
                                              const std::vector<double>& fields);

}  // namespace lenslab
