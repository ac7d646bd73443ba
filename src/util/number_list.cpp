#include "util/number_list.h"

#include <cmath>
#include <stdexcept>

namespace lenslab {

std::vector<double> parse_number_list(const std::string& text, char separator) {
    std::vector<double> values;
    if (text.find_first_not_of(" \t") == std::string::npos) return values;
    size_t from = 0;
    while (from <= text.size()) {
        const size_t at = std::min(text.find(separator, from), text.size());
        const std::string part = text.substr(from, at - from);
        from = at + 1;
        const size_t first = part.find_first_not_of(" \t");
        if (first == std::string::npos) {
            throw std::invalid_argument("'" + text + "': a number is missing (an empty part)");
        }
        const size_t last = part.find_last_not_of(" \t");
        const std::string number = part.substr(first, last - first + 1);
        size_t used = 0;
        double v = 0;
        try {
            v = std::stod(number, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != number.size() || !std::isfinite(v)) {
            throw std::invalid_argument("'" + text + "': '" + number + "' is not a number");
        }
        values.push_back(v);
    }
    return values;
}

}  // namespace lenslab
