#pragma once
// Constants shared across the library (one definition, so unity builds see one).

#include <numbers>

namespace lenslab {

inline constexpr double kPi = std::numbers::pi;

}  // namespace lenslab
