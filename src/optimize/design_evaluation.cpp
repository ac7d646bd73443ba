#include "optimize/design_evaluation.h"

#include <cmath>
#include <stdexcept>

#include "analysis/aberrations/field_curves.h"
#include "analysis/aberrations/polychromatic_spot.h"
#include "analysis/diffraction/field_mtf.h"
#include "analysis/diffraction/weighted_wavelengths.h"
#include "analysis/diffraction/zernike.h"
#include "analysis/system/field_beam.h"
#include "analysis/system/first_order.h"
#include "analysis/system/paraxial.h"
#include "analysis/system/ray_aiming.h"
#include "optimize/design_configurations.h"
#include "optimize/model_glass.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"

namespace lenslab {

namespace {

// Axial thickness of an element at distance r from the axis.
double de_thickness_at(const OpticalSystem& system, const SystemElement& e, double r) {
    return system.surfaces[e.last_surface].z_at(r) - system.surfaces[e.first_surface].z_at(r);
}

const SystemElement& de_element(const OpticalSystem& system, const Scene& scene, int object,
                                const std::string& path) {
    for (const SystemElement& e : system.elements) {
        if (scene.objects[e.object].source == object) return e;
    }
    throw SceneError(path, "the lens is not part of the optical system");
}

// Thrown where rays a spot needs are lost.
struct RaysLost {
    std::string why;
};

// The optimiser's wavefronts: coarse and fixed, since a sampling that changed between two
// designs would break the finite differences of the Jacobian.
constexpr int kWavefrontOperandSamples = 32, kMtfOperandSamples = 32;

// The polychromatic RMS wavefront of a field about its best tilt (piston and tilt removed, the
// PSF's centroid as reference), in waves: √(Σ w rms² / Σ w). `lost`: the rays the wavefronts
// lost, all wavelengths.
double de_rms_wavefront(const OpticalSystem& system, const FirstOrder& first, const LensDesign& d,
                        double field, double image_z, int* lost) {
    const WeightedWavelengths chosen = weighted_wavelengths(first, d.wavelengths, d.weights);
    double sum = 0;
    *lost = 0;
    for (size_t k = 0; k < chosen.nm.size(); ++k) {
        FieldWavefrontOptions o;
        o.field = field;
        o.wavelength_nm = chosen.nm[k];
        o.sampling = {kWavefrontOperandSamples, 2};
        o.image_z = image_z;
        const FieldWavefront w = field_wavefront(system, first, o);
        const double rms = fit_zernike(w.pupil, ZernikeOrdering::Noll, 3).residual_rms;
        sum += chosen.weights[k] * rms * rms;
        *lost += w.lost;
    }
    return std::sqrt(sum / chosen.total);
}

// The field's distortion in percent at the primary wavelength: the real chief ray's height
// in the image plane against the paraxial chief ray's (the bench's field curves).
double de_distortion(const OpticalSystem& system, const FirstOrder& first, const LensDesign& d,
                     const MeritOperand& op, double image_z) {
    FieldCurveOptions options;
    options.max_field = op.field;
    options.points = 2;  // the axis and the field
    options.wavelengths = {d.primary_wavelength()};
    options.image_z = image_z;
    const double distortion =
        field_curves(system, first, options).curves.front().points.back().distortion;
    if (!std::isfinite(distortion))
        throw RaysLost{op.path + ": " + operand_label(op) + ": the chief ray is lost"};
    return 100 * distortion;
}

double de_mtf(const OpticalSystem& system, const FirstOrder& first, const LensDesign& d,
              const MeritOperand& op, double image_z) {
    FieldMtfOptions o;
    o.fields = {op.field};
    o.wavelengths = d.wavelengths;
    o.weights = d.weights;
    o.frequencies = {op.frequency};
    o.samples = kMtfOperandSamples;
    o.resolve = false;
    o.image_z = image_z;
    const FieldMtf m = field_mtfs(system, first, o).fields[0];
    if (!m.error.empty()) throw std::invalid_argument(m.error);
    if (op.direction == "tangential") return m.tangential[0];
    if (op.direction == "sagittal") return m.sagittal[0];
    return 0.5 * (m.tangential[0] + m.sagittal[0]);
}

}  // namespace

std::vector<double> DesignModel::Configuration::local(const std::vector<double>& x) const {
    std::vector<double> out;
    out.reserve(globals.size());
    for (int i : globals) out.push_back(x[size_t(i)]);
    return out;
}

DesignModel::DesignModel(const LensDesign& design) : m_design(design) {
    if (!design.configurations.empty()) {
        for (size_t k = 0; k < design.configurations.size(); ++k) {
            Configuration c;
            const LensDesign one = configuration_design(design, int(k), &c.globals);
            try {
                c.model = std::make_shared<const DesignModel>(one);
            } catch (const SceneError& e) {
                throw SceneError(e.path(), "configuration '" + design.configurations[k].name +
                                               "': " + e.reason());
            }
            m_configurations.push_back(std::move(c));
        }
        m_start = m_configurations.front().model->state_at(m_configurations.front().model->start());
        return;
    }
    m_start.scene = design.scene;
    m_start.image_distance = design.image_distance.value_or(0.0);
    m_start_lost.assign(design.operands.size(), 0);
    try {
        evaluate_state(m_start, &m_start_lost);
    } catch (const RaysLost& lost) {
        throw SceneError("operands", lost.why);
    }
}

std::vector<double> DesignModel::start() const {
    if (!m_configurations.empty()) {
        // Each variable where the first configuration that has it starts it.
        std::vector<double> x(m_design.variables.size());
        std::vector<bool> known(x.size(), false);
        for (const Configuration& c : m_configurations) {
            const std::vector<double> local = c.model->start();
            for (size_t j = 0; j < c.globals.size(); ++j) {
                if (known[size_t(c.globals[j])]) continue;
                x[size_t(c.globals[j])] = local[j];
                known[size_t(c.globals[j])] = true;
            }
        }
        return x;
    }
    std::vector<double> x;
    for (const DesignVariable& v : m_design.variables) x.push_back(variable_value(m_start, v));
    return x;
}

DesignState DesignModel::state_at(const std::vector<double>& x) const {
    if (!m_configurations.empty()) {
        const Configuration& first = m_configurations.front();
        return first.model->state_at(first.local(x));
    }
    DesignState state = m_start;
    const std::vector<double> x0 = start();
    for (size_t i = 0; i < x.size(); ++i) {
        // A variable left where it started keeps its number as written (1/(1/R) may not
        // give R back to the last bit).
        if (x[i] != x0[i]) set_variable(state, m_design.variables[i], x[i]);
    }
    return state;
}

std::vector<DesignState> DesignModel::configuration_states(const std::vector<double>& x) const {
    if (m_configurations.empty()) return {state_at(x)};
    std::vector<DesignState> states;
    for (const Configuration& c : m_configurations) states.push_back(c.model->state_at(c.local(x)));
    return states;
}

std::optional<DesignEvaluation> DesignModel::evaluate(const std::vector<double>& x,
                                                      std::string* why) const {
    if (!m_configurations.empty()) {
        // The configurations' operands one after the other, as the design lists them.
        DesignEvaluation all;
        for (const Configuration& c : m_configurations) {
            const std::optional<DesignEvaluation> e = c.model->evaluate(c.local(x), why);
            if (!e) return std::nullopt;
            const auto append = [](std::vector<double>& to, const std::vector<double>& from) {
                to.insert(to.end(), from.begin(), from.end());
            };
            append(all.values, e->values);
            append(all.residuals, e->residuals);
            append(all.solver_residuals, e->solver_residuals);
            all.merit += e->merit;
            all.configuration_efl.push_back(e->efl);
            all.configuration_image_distance.push_back(e->image_distance);
        }
        all.efl = all.configuration_efl.front();
        all.image_distance = all.configuration_image_distance.front();
        return all;
    }
    try {
        return evaluate_state(state_at(x), nullptr);
    } catch (const Error& e) {
        if (why) *why = e.what();
    } catch (const RaysLost& lost) {
        if (why) *why = lost.why;
    }
    return std::nullopt;
}

DesignEvaluation DesignModel::evaluate_state(const DesignState& state,
                                             std::vector<int>* record_lost) const {
    const LensDesign& d = m_design;
    const Scene scene =
        scene_from_json(nlohmann::json(state.scene), d.base_dir, {.require_camera = false});
    OpticalSystem system = build_optical_system(scene);
    int stop = d.stop;
    if (d.stop_in_air) {
        const SystemElement& e =
            de_element(system, scene, d.stop_in_air->object, "stop_in_air.lens");
        try {
            stop =
                insert_air_stop(system, system.surfaces[e.last_surface].z + d.stop_in_air->distance,
                                system.max_semi_diameter());
        } catch (const SceneError& err) {  // named by the design's key, not the bench's
            throw SceneError("stop_in_air.distance", err.reason());
        }
    }
    const double primary = d.primary_wavelength();
    const ParaxialResult paraxial = paraxial_trace(system, primary);
    FirstOrderOptions options;
    options.wavelength_nm = primary;
    options.stop = stop;
    options.epd = d.epd;
    options.f_number = d.f_number;
    options.fields = d.fields;
    options.ray_aiming = d.ray_aiming;
    const FirstOrder first = first_order(system, paraxial, options);
    DesignEvaluation result;
    result.efl = paraxial.efl;
    result.image_distance = d.image_distance ? state.image_distance : first.image_position;
    const double image_z = system.last_vertex() + result.image_distance;
    std::vector<double> deviations;
    for (size_t i = 0; i < d.operands.size(); ++i) {
        const MeritOperand& op = d.operands[i];
        double value = 0;
        bool per_ray_done = false;
        switch (op.kind) {
            case OperandKind::Efl:
                value = paraxial.efl;
                break;
            case OperandKind::Bfl:
                value = paraxial.bfl;
                break;
            case OperandKind::EntrancePupilPosition:
            case OperandKind::ExitPupilPosition:
                value = op.kind == OperandKind::EntrancePupilPosition
                            ? first.entrance_pupil.position
                            : first.exit_pupil.position;
                // A pupil at infinity (telecentric) has no distance to aim at.
                if (!std::isfinite(value))
                    throw RaysLost{op.path + ": " + operand_label(op) +
                                   ": the pupil is at infinity"};
                break;
            case OperandKind::Distortion:
                value = de_distortion(system, first, d, op, image_z);
                break;
            case OperandKind::RmsSpot: {
                const bool per_ray = op.target == 0 && (record_lost || m_start_lost[i] == 0);
                deviations.clear();
                const PolychromaticSpot spot =
                    polychromatic_rms_spot(system, first, op.field, d.wavelengths, d.weights,
                                           d.rings, image_z, per_ray ? &deviations : nullptr);
                // More rays lost than at the start: the step has pushed the beam off the
                // lenses, and a spot of the rays left would look better than it is.
                if (record_lost) (*record_lost)[i] = spot.lost;
                const int allowed = record_lost ? spot.lost : m_start_lost[i];
                if (!std::isfinite(spot.rms_radius) || spot.lost > allowed) {
                    throw RaysLost{op.path + ": " + operand_label(op) + " loses " +
                                   std::to_string(spot.lost) + " of " + std::to_string(spot.rays) +
                                   " rays"};
                }
                value = spot.rms_radius;
                // At the start, per ray only if no ray is lost (the residuals' count is then
                // every ray's, and stays so).
                if (per_ray && spot.lost == 0) {
                    for (double r : deviations) {
                        result.solver_residuals.push_back(std::sqrt(op.weight) * r);
                    }
                    per_ray_done = true;
                }
                break;
            }
            case OperandKind::RmsWavefront:
            case OperandKind::Mtf:
                try {
                    if (op.kind == OperandKind::Mtf) {
                        value = de_mtf(system, first, d, op, image_z);
                        break;
                    }
                    int lost = 0;
                    value = de_rms_wavefront(system, first, d, op.field, image_z, &lost);
                    // As for the spot: more rays lost than at the start is a step off the lenses.
                    if (record_lost) (*record_lost)[i] = lost;
                    if (lost > (record_lost ? lost : m_start_lost[i]))
                        throw RaysLost{op.path + ": " + operand_label(op) + " loses " +
                                       std::to_string(lost) + " rays"};
                } catch (const std::invalid_argument& e) {
                    throw RaysLost{op.path + ": " + operand_label(op) + ": " + e.what()};
                }
                break;
            case OperandKind::RealRayX:
            case OperandKind::RealRayY: {
                const RayAimer aimer(system, first, op.field, primary);
                const std::optional<ExitRay> out =
                    passed_exit_ray(system, aimer.trace(op.px, op.py));
                if (!out) throw RaysLost{op.path + ": " + operand_label(op) + ": the ray is lost"};
                const Vec3 p = at_plane(out->point, out->direction, image_z);
                value = op.kind == OperandKind::RealRayX ? p.x : p.y;
                break;
            }
            case OperandKind::MinCenterThickness:
            case OperandKind::MaxCenterThickness:
                value = de_thickness_at(system, de_element(system, scene, op.object, op.path), 0);
                break;
            case OperandKind::MinEdgeThickness: {
                const SystemElement& e = de_element(system, scene, op.object, op.path);
                value = de_thickness_at(system, e, e.semi_diameter);
                break;
            }
            case OperandKind::MaxTotalLength:
                value = image_z;
                break;
            case OperandKind::GlassDistance: {
                const nlohmann::ordered_json& ior =
                    state.scene["objects"][op.object]["material"]["ior"];
                const double n_d = ior["n_d"].get<double>(), v_d = ior["V_d"].get<double>();
                const std::vector<const Glass*> nearest =
                    nearest_catalogue_glasses(n_d, v_d, d.glass_substitution.makers, 1);
                value = nearest.empty() ? 0.0 : glass_map_distance(n_d, v_d, *nearest.front());
                break;
            }
        }
        const double residual = operand_residual(op, value);
        result.values.push_back(value);
        result.residuals.push_back(std::sqrt(op.weight) * residual);
        if (!per_ray_done) result.solver_residuals.push_back(result.residuals.back());
        result.merit += op.weight * residual * residual;
    }
    return result;
}

}  // namespace lenslab
