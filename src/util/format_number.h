#pragma once
// Numbers in messages and written formulas, the way a user types them: 5, -1, 0.25, 1e-05;
// ten significant digits, enough that a value read back is the one meant.

#include <string>

namespace lenslab {

std::string format_number(double v);

// printf's formatting into a string of any length: the reports' aligned columns and the
// figures' fixed-precision labels. The compiler checks the arguments against the format.
std::string printf_text(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace lenslab
