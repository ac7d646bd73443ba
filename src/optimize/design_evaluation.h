#pragma once
// One evaluation of a design's merit function at a point of its variables: the scene
// rebuilt with the variables' values written in (the reader re-checks it: faces that cross
// are refused there), its optical system, the paraxial focal length and image plane, and
// every operand's value. A point that cannot be evaluated (the scene is refused, the system
// is afocal, a spot loses rays the starting design did not) has no evaluation: the
// optimiser treats it as a failed step.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "optimize/lens_design.h"

namespace lenslab {

struct DesignEvaluation {
    std::vector<double> values;     // one per operand
    std::vector<double> residuals;  // sqrt(weight) * residual, one per operand
    // What damped least squares minimises, the same sum of squares (the merit): each operand's
    // residual, except an RMS spot with target 0 and no ray lost at the start, which gives
    // one residual per ray and axis (polychromatic_spot.h). Its length never changes: a
    // point losing a ray such a spot needs cannot be evaluated.
    std::vector<double> solver_residuals;
    double merit = 0;           // sum of weight * residual²
    double efl = 0;             // paraxial, primary wavelength
    double image_distance = 0;  // from the last vertex
    // A multi-configuration design's EFL and image distance in each configuration (the two
    // above are the first's); empty for one configuration.
    std::vector<double> configuration_efl, configuration_image_distance;
};

class DesignModel {
public:
    // Evaluates the start; throws SceneError when even that cannot be evaluated.
    explicit DesignModel(const LensDesign& design);

    const LensDesign& design() const { return m_design; }
    std::vector<double> start() const;  // the variables' starting values
    // The design at `x`: a multi-configuration design's first configuration.
    DesignState state_at(const std::vector<double>& x) const;
    // Each configuration's state at `x` (one: state_at's).
    std::vector<DesignState> configuration_states(const std::vector<double>& x) const;
    // None where the point cannot be evaluated; `why` then says why.
    std::optional<DesignEvaluation> evaluate(const std::vector<double>& x,
                                             std::string* why = nullptr) const;

private:
    // `record_lost`: the start, whose lost rays set what later points may lose.
    DesignEvaluation evaluate_state(const DesignState& state, std::vector<int>* record_lost) const;

    // A multi-configuration design's configuration: a design of one, and the index in the
    // design's variables of each of its variables.
    struct Configuration {
        std::shared_ptr<const DesignModel> model;
        std::vector<int> globals;
        std::vector<double> local(const std::vector<double>& x) const;
    };

    LensDesign m_design;
    DesignState m_start;
    std::vector<int> m_start_lost;                // rays each rms_spot operand lost at the start
    std::vector<Configuration> m_configurations;  // empty for one configuration
};

}  // namespace lenslab
