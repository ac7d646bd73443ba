#pragma once
// Numbers in messages and written formulas, the way a user types them: 5, -1, 0.25, 1e-05;
// ten significant digits, enough that a value read back is the one meant.

#include <string>

namespace lenslab {

std::string format_number(double v);

}  // namespace lenslab
