#include "util/format_number.h"

#include <cstdio>

namespace lenslab {

std::string format_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

}  // namespace lenslab
