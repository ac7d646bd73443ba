#include "optimize/tolerance_report.h"

namespace lenslab {

namespace {

nlohmann::json optional_number(const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json();
}

}  // namespace

nlohmann::ordered_json tolerance_json(const ToleranceReport& r) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const SensitivityRow& row : r.rows) {
        rows.push_back({{"tolerance", row.label},
                        {"plus_minus", row.tolerance},
                        {"criterion_minus", optional_number(row.minus)},
                        {"criterion_plus", optional_number(row.plus)}});
    }
    const MonteCarloSummary& m = r.monte_carlo;
    return {{"criterion", r.criterion},
            {"refocus", r.compensated},
            {"nominal", r.nominal},
            {"nominal_fields", r.nominal_fields},
            {"image_distance", r.image_distance},
            {"sensitivity", rows},
            {"rss_change", r.rss_change},
            {"predicted_mean", r.predicted_mean},
            {"predicted_sd", r.predicted_sd},
            {"monte_carlo",
             {{"trials", m.trials},
              {"failed", m.failed},
              {"mean", m.mean},
              {"sd", m.sd},
              {"min", m.min},
              {"p50", m.p50},
              {"p90", m.p90},
              {"p98", m.p98},
              {"max", m.max},
              {"criteria", m.criteria}}}};
}

}  // namespace lenslab
