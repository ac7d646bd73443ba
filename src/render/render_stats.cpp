#include "render/render_stats.h"

#include <stdexcept>

namespace lenslab {

double RenderStats::value(std::string_view name) const {
    for (const RenderStat& v : values) {
        if (v.name == name) return v.value;
    }
    throw std::out_of_range("no render statistic '" + std::string(name) + "'");
}

}  // namespace lenslab
