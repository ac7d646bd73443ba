#include "optimize/tolerance.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "cluster/cluster_session.h"
#include "cluster/dealt_parts.h"
#include "math/rng.h"
#include "optics/glass_library.h"
#include "optimize/design_evaluation.h"
#include "util/format_number.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// Trials run in chunks of this many between progress reports.
constexpr int kTrialChunk = 64;
// Refocusing: rounds of the parabola through three image planes, each a quarter the last's
// spacing, the first spacing this share of the image distance (at least kLeastFocusStep).
constexpr int kRefocusRounds = 3;
constexpr double kFocusStepShare = 0.002, kLeastFocusStep = 1e-4;

// The variable `spec` of the design's system, or none where the system refuses it (a flat or
// formula face, no lens behind for an air gap).
std::optional<DesignVariable> try_variable(const LensDesign& design, const nlohmann::json& spec) {
    try {
        return read_design_variable(spec, "tolerance", design.scene);
    } catch (const SceneError&) {
        return std::nullopt;
    }
}

// The V_d of lens `object`'s catalogue glass, none when its material names no glass.
std::optional<double> catalogue_abbe_number(const nlohmann::ordered_json& scene, int object) {
    const nlohmann::ordered_json* m = lens_material(scene, object);
    if (!m || !m->is_object() || !m->contains("glass") || !(*m)["glass"].is_string()) {
        return std::nullopt;
    }
    const GlassLookup found = lookup_glass((*m)["glass"].get<std::string>());
    if (!found.glass) return std::nullopt;
    return found.glass->model->abbe_number();
}

// The design with the criterion's operands (one a field) and no variables.
LensDesign criterion_design(const LensDesign& design) {
    LensDesign d = design;
    d.variables.clear();
    d.operands.clear();
    const ToleranceSettings& t = design.tolerances;
    for (size_t i = 0; i < design.fields.size(); ++i) {
        MeritOperand op;
        op.kind = t.criterion == "mtf"             ? OperandKind::Mtf
                  : t.criterion == "rms_wavefront" ? OperandKind::RmsWavefront
                                                   : OperandKind::RmsSpot;
        op.frequency = t.frequency;
        op.direction = "mean";
        op.field = design.fields[i];
        op.path = "fields[" + std::to_string(i) + "]";
        d.operands.push_back(op);
    }
    // An MTF's lens is refocused by its spots.
    for (size_t i = 0; t.criterion == "mtf" && t.refocus && i < design.fields.size(); ++i) {
        MeritOperand op;
        op.kind = OperandKind::RmsSpot;
        op.field = design.fields[i];
        op.path = "fields[" + std::to_string(i) + "]";
        d.operands.push_back(op);
    }
    return d;
}

// The root mean square of values [first, last) of an evaluation.
double rms_of(const DesignEvaluation& e, size_t first, size_t last) {
    double sum = 0;
    for (size_t i = first; i < last; ++i) sum += e.values[i] * e.values[i];
    return std::sqrt(sum / double(last - first));
}

// The criterion as a badness the table's predictions work in, 0 at best: the RMS over the
// fields of the spots or wavefronts, or 1 - the mean MTF over the fields (criterion_design's
// first `fields` operands; after them, a refocused MTF's RMS spots).
double badness_of(const DesignEvaluation& e, bool mtf, size_t fields) {
    if (!mtf) return rms_of(e, 0, fields);
    double sum = 0;
    for (size_t i = 0; i < fields; ++i) sum += e.values[i];
    return 1 - sum / double(fields);
}

// What the back focus is set by: the criterion, or for an MTF the RMS spot.
double focus_badness_of(const DesignEvaluation& e, bool mtf, size_t fields) {
    return mtf && e.values.size() > fields ? rms_of(e, fields, e.values.size())
                                           : badness_of(e, mtf, fields);
}

// A made lens measured: the badness the back focus is set by (the criterion's; for an MTF,
// the RMS spot's, which is smooth across focus where an MTF at one frequency may have more
// than one peak) and the criterion's badness there.
struct Measure {
    double focus = 0, criterion = 0;
};

class Criterion {
public:
    Criterion(const DesignModel& model, bool refocus, double focus_step, bool mtf)
        : m_model(model),
          m_refocus(refocus),
          m_step(focus_step),
          m_mtf(mtf),
          m_fields(model.design().fields.size()) {}

    // At `x` (the last coordinate the image distance); refocused when asked: the parabola
    // through the squared focus badness at three image planes, narrowed kRefocusRounds times.
    std::optional<double> operator()(std::vector<double> x) const { return focused(x).first; }

    // The criterion's badness and the image distance it was found at.
    std::pair<std::optional<double>, double> focused(std::vector<double> x) const {
        std::optional<Measure> best = at(x);
        if (!best) return {std::nullopt, x.back()};
        if (!m_refocus) return {best->criterion, x.back()};
        double z = x.back(), h = m_step;
        for (int round = 0; round < kRefocusRounds; ++round, h /= 4) {
            x.back() = z - h;
            const std::optional<Measure> before = at(x);
            x.back() = z + h;
            const std::optional<Measure> after = at(x);
            if (!before || !after) break;
            const double f0 = best->focus * best->focus, fm = before->focus * before->focus,
                         fp = after->focus * after->focus;
            double next = fm < fp ? z - h : z + h;
            Measure next_value = fm < fp ? *before : *after;
            const double curvature = fp - 2 * f0 + fm;
            if (curvature > 0) {
                const double shift = std::clamp(-h * (fp - fm) / (2 * curvature), -4 * h, 4 * h);
                x.back() = z + shift;
                if (const std::optional<Measure> v = at(x); v && v->focus < next_value.focus) {
                    next = z + shift;
                    next_value = *v;
                }
            }
            if (next_value.focus < best->focus) {
                best = next_value;
                z = next;
            }
        }
        return {best->criterion, z};
    }

private:
    std::optional<Measure> at(const std::vector<double>& x) const {
        const std::optional<DesignEvaluation> e = m_model.evaluate(x);
        if (!e) return std::nullopt;
        return Measure{focus_badness_of(*e, m_mtf, m_fields), badness_of(*e, m_mtf, m_fields)};
    }

    const DesignModel& m_model;
    bool m_refocus;
    double m_step;
    bool m_mtf;
    size_t m_fields;
};

// The nearest-rank percentile `p` (0-100) of sorted values.
double percentile(const std::vector<double>& sorted, double p) {
    const size_t rank = size_t(std::ceil(p / 100 * double(sorted.size())));
    return sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
}

MonteCarloSummary summarise(const std::vector<std::optional<double>>& trials) {
    MonteCarloSummary s;
    s.trials = int(trials.size());
    for (const std::optional<double>& t : trials) {
        if (t) s.criteria.push_back(*t);
    }
    s.failed = s.trials - int(s.criteria.size());
    if (s.criteria.empty()) return s;
    double sum = 0, sum2 = 0;
    for (double c : s.criteria) sum += c, sum2 += c * c;
    const double n = double(s.criteria.size());
    s.mean = sum / n;
    s.sd = std::sqrt(std::max(0.0, sum2 / n - s.mean * s.mean));
    std::vector<double> sorted = s.criteria;
    std::sort(sorted.begin(), sorted.end());
    s.min = sorted.front();
    s.max = sorted.back();
    s.p50 = percentile(sorted, 50);
    s.p90 = percentile(sorted, 90);
    s.p98 = percentile(sorted, 98);
    return s;
}

// The report's badness figures as MTFs (1 - badness): the spread and the changes keep their
// size, the least badness is the highest MTF, and a percentile's lenses are at or above it.
void as_mtf(ToleranceReport& r) {
    const auto mtf = [](double b) { return 1 - b; };
    const auto mtf_or_none = [&](std::optional<double>& v) {
        if (v) v = mtf(*v);
    };
    r.nominal = mtf(r.nominal);
    for (SensitivityRow& row : r.rows) {
        mtf_or_none(row.minus);
        mtf_or_none(row.plus);
    }
    r.predicted_mean = mtf(r.predicted_mean);
    MonteCarloSummary& m = r.monte_carlo;
    if (m.criteria.empty()) return;
    m.mean = mtf(m.mean);
    std::swap(m.min, m.max);
    for (double* v : {&m.min, &m.max, &m.p50, &m.p90, &m.p98}) *v = mtf(*v);
    for (double& c : m.criteria) c = mtf(c);
}

}  // namespace

double ToleranceItem::value_at(double e) const {
    if (variable.kind == VariableKind::Curvature) return 1 / (1 / nominal + e);
    return nominal + e;
}

std::vector<ToleranceItem> tolerance_items(const LensDesign& design) {
    const ToleranceSettings& t = design.tolerances;
    DesignState state{design.scene, design.image_distance.value_or(0)};
    std::vector<ToleranceItem> items;
    // `shown`: the tolerance as the label gives it (default: in the variable's unit).
    const auto add = [&](const nlohmann::json& spec, const std::string& label, double tolerance,
                         const std::string& shown = "") {
        if (tolerance <= 0) return;
        const std::optional<DesignVariable> v = try_variable(design, spec);
        if (!v) return;
        const double nominal = variable_value(state, *v);
        // A flat face (curvature 0) has no radius to be made wrong.
        if (v->kind == VariableKind::Curvature && nominal == 0) return;
        items.push_back({*v, label + " ± " + (shown.empty() ? format_number(tolerance) : shown),
                         nominal, tolerance});
    };
    for (const DesignLens& lens : design_lenses(design.scene)) {
        const std::string& name = lens.name;
        for (const char* face : {"front", "back"}) {
            add({{"type", "curvature"}, {"lens", name}, {"surface", face}},
                "radius " + name + "." + face, t.radius);
        }
        add({{"type", "thickness"}, {"lens", name}}, "thickness " + name, t.thickness);
        add({{"type", "air_gap"}, {"lens", name}}, "air gap after " + name, t.air_gap);
        // The bench does not measure a gradient-index lens moved from its axis.
        const nlohmann::ordered_json* material = lens_material(design.scene, lens.object);
        const bool grin = material && material->is_object() && material->contains("grin");
        for (const char* axis : {"x", "y"}) {
            if (grin) break;
            add({{"type", std::string("decenter_") + axis}, {"lens", name}},
                std::string("decentre ") + axis + " " + name, t.decenter);
            add({{"type", std::string("tilt_") + axis}, {"lens", name}},
                std::string("tilt ") + axis + " " + name, t.tilt, format_number(t.tilt) + "°");
        }
        add({{"type", "delta_n_d"}, {"lens", name}}, "n_d " + name, t.index);
        // The Abbe number's tolerance is a share of the glass's own.
        if (const std::optional<double> v_d = catalogue_abbe_number(design.scene, lens.object)) {
            add({{"type", "delta_V_d"}, {"lens", name}}, "V_d " + name, t.abbe / 100 * *v_d,
                format_number(t.abbe) + "%");
        }
    }
    return items;
}

ToleranceReport tolerance_design(const LensDesign& design,
                                 const std::function<void(int, int)>& progress) {
    if (!design.configurations.empty()) {
        throw SceneError("configurations", "tolerancing of multi-configuration designs: not yet");
    }
    ToleranceReport report;
    report.compensated = design.tolerances.refocus;
    report.criterion = design.tolerances.criterion;
    report.higher_is_better = report.criterion == "mtf";
    // The nominal image plane: the design's, or its paraxial focus.
    LensDesign measured = criterion_design(design);
    {
        const DesignModel nominal(measured);
        const std::optional<DesignEvaluation> e = nominal.evaluate(nominal.start());
        if (!e) throw SceneError("system", "the nominal design cannot be evaluated");
        report.image_distance = e->image_distance;
    }
    measured.image_distance = report.image_distance;
    const std::vector<ToleranceItem> items = tolerance_items(design);
    for (const ToleranceItem& item : items) measured.variables.push_back(item.variable);
    DesignVariable image;
    image.kind = VariableKind::ImageDistance;
    image.path = "image_distance";
    measured.variables.push_back(image);

    const DesignModel model(measured);
    const std::vector<double> x0 = model.start();
    const Criterion criterion(
        model, design.tolerances.refocus,
        std::max(kLeastFocusStep, kFocusStepShare * std::abs(report.image_distance)),
        report.higher_is_better);
    {
        // The nominal lens refocused as the made ones are, so they are compared alike.
        std::vector<double> x = x0;
        x.back() = criterion.focused(x0).second;
        const std::optional<DesignEvaluation> e = model.evaluate(x);
        report.nominal = badness_of(*e, report.higher_is_better, design.fields.size());
        report.nominal_fields.assign(e->values.begin(),
                                     e->values.begin() + std::ptrdiff_t(design.fields.size()));
        report.image_distance = x.back();
    }

    // The sensitivity table: each error alone at both ends.
    report.rows.resize(items.size());
    tbb::parallel_for(size_t{0}, items.size(), [&](size_t i) {
        SensitivityRow& row = report.rows[i];
        row.label = items[i].label;
        row.tolerance = items[i].tolerance;
        for (const double sign : {-1.0, 1.0}) {
            std::vector<double> x = x0;
            x[i] = items[i].value_at(sign * items[i].tolerance);
            (sign < 0 ? row.minus : row.plus) = criterion(x);
        }
    });
    const double n2 = report.nominal * report.nominal;
    double rss = 0, spread = 0, mean_square = n2;
    for (const SensitivityRow& row : report.rows) {
        if (!row.minus || !row.plus) continue;
        const double worst =
            std::max({*row.minus - report.nominal, *row.plus - report.nominal, 0.0});
        rss += worst * worst;
        spread += (*row.plus - *row.minus) * (*row.plus - *row.minus) / 4 / 3;
        mean_square += ((*row.minus * *row.minus + *row.plus * *row.plus) / 2 - n2) / 3;
    }
    report.rss_change = std::sqrt(rss);
    report.predicted_sd = std::sqrt(spread);
    report.predicted_mean = std::sqrt(std::max(0.0, mean_square));

    // The Monte Carlo: every error at once, uniform within its tolerance. In a job of several
    // ranks, chunk c of trials is dealt to rank c mod N and the criteria shared afterwards: a
    // trial's errors come from its own stream, so every rank ends with one process's report.
    const int trials = design.tolerances.trials;
    const int chunks = (trials + kTrialChunk - 1) / kTrialChunk;
    Communicator& comm = world_communicator();
    std::vector<std::vector<double>> criteria(static_cast<size_t>(chunks));  // NaN: failed
    for (int chunk = 0; chunk < chunks; ++chunk) {
        const int first = chunk * kTrialChunk, last = std::min(trials, first + kTrialChunk);
        if (!dealt_to(chunk, comm)) continue;
        std::vector<double>& part = criteria[size_t(chunk)];
        part.resize(size_t(last - first));
        tbb::parallel_for(first, last, [&](int trial) {
            Rng rng(design.tolerances.seed, uint64_t(trial));
            std::vector<double> x = x0;
            for (size_t i = 0; i < items.size(); ++i) {
                x[i] = items[i].value_at((2 * rng.uniform() - 1) * items[i].tolerance);
            }
            part[size_t(trial - first)] = criterion(x).value_or(std::nan(""));
        });
        if (progress) progress(last, trials);
    }
    share_dealt_parts(comm, criteria);
    if (progress && !comm.alone()) progress(trials, trials);  // the other ranks' chunks too
    std::vector<std::optional<double>> results;
    results.reserve(size_t(trials));
    for (const std::vector<double>& part : criteria) {
        for (double c : part) results.push_back(std::isnan(c) ? std::nullopt : std::optional(c));
    }
    report.monte_carlo = summarise(results);
    if (report.higher_is_better) as_mtf(report);
    return report;
}

}  // namespace lenslab
