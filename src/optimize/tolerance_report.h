#pragma once
// A tolerance report as JSON: what `lenslab tolerance --json` prints and lenslab.tolerance
// returns (docs/optimizer.md#tolerancing).

#include <nlohmann/json.hpp>

#include "optimize/tolerance.h"

namespace lenslab {

nlohmann::ordered_json tolerance_json(const ToleranceReport& report);

}  // namespace lenslab
