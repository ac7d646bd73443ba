#pragma once
// The first-order data and the Seidel sums as `lenslab analyze` prints them: JSON (keys
// `first_order` and `seidel`) and text tables.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/aberrations/seidel.h"
#include "analysis/system/first_order.h"

namespace lenslab {

nlohmann::ordered_json first_order_json(const OpticalSystem& system, const FirstOrder& f);
nlohmann::ordered_json seidel_json(const OpticalSystem& system, const Seidel& s);
std::string first_order_table(const OpticalSystem& system, const FirstOrder& f);
std::string seidel_table(const OpticalSystem& system, const Seidel& s);

}  // namespace lenslab
