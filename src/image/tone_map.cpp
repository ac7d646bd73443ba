#include "image/tone_map.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

PixelRgb ToneMap::apply(const PixelRgb& linear) const {
    const float scale = float(std::exp2(exposure_stops));
    PixelRgb p{linear.r * scale, linear.g * scale, linear.b * scale};
    // The brightest channel sets the scale of all three: none then passes 1, so a
    // saturated highlight keeps its hue and saturation, not only its luminance.
    const double m = std::max({p.r, p.g, p.b});
    if (log_highlights && m > kToneMapKnee) {
        // Continuous at the knee; white at knee * 2^highlight_stops and beyond.
        const double stops = std::log2(m / kToneMapKnee) / highlight_stops;
        const double shown = kToneMapKnee + (1.0 - kToneMapKnee) * std::min(stops, 1.0);
        const float f = float(shown / m);
        p = {p.r * f, p.g * f, p.b * f};
    }
    return {std::clamp(p.r, 0.0f, 1.0f), std::clamp(p.g, 0.0f, 1.0f), std::clamp(p.b, 0.0f, 1.0f)};
}

}  // namespace lenslab
