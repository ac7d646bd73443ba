#pragma once
// The bench figures of a sweep (`lenslab sweep --analyze`) as one table: a row per frame with
// the swept values and the scalar figures of that frame's `analyze --json` document, for
// sweep.csv, and the same as JSON for sweep.json.

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "scene/sweep_plan.h"

namespace lenslab {

// The scalar figures of one `analyze --json` document, in its order: every number at the top
// level (efl, bfl, rms_spot_best, ...) and every number directly inside a top-level object,
// named "object.key" (first_order.f_number, chromatic.efl_F, ...). Arrays are left out.
std::vector<std::pair<std::string, nlohmann::ordered_json>> bench_figures(
    const nlohmann::ordered_json& report);

// The CSV: a header "frame,POINTER...,FIGURE..." and a row per frame; reports[i] is frame i's
// document. A figure one frame lacks (a chief ray that could not be traced) is an empty cell.
std::string sweep_csv(const SweepPlan& plan, const std::vector<nlohmann::ordered_json>& reports);

// sweep.json: the scene, the parameters, and per frame its values and its file (`frame_files`
// [i]); with `reports` (a sweep --analyze), each frame's bench_figures too.
nlohmann::ordered_json sweep_summary_json(const SweepPlan& plan, const std::string& scene_file,
                                          const std::vector<std::string>& frame_files,
                                          const std::vector<nlohmann::ordered_json>& reports = {});

}  // namespace lenslab
