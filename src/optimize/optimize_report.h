#pragma once
// The report of `lenslab optimize`: the merit function and every operand before and after
// (value, target or limit, weight, contribution), the variables' values, and why the solver
// stopped; as a table or as JSON.

#include <nlohmann/json.hpp>
#include <string>

#include "optimize/optimize_design.h"

namespace lenslab {

std::string optimize_table(const OptimizeResult& result);
nlohmann::ordered_json optimize_json(const OptimizeResult& result);

}  // namespace lenslab
