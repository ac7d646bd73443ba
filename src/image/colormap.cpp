#include "image/colormap.h"

#include <algorithm>

namespace lenslab {

Rgb inferno(double t) {
    // Matplotlib's inferno (van der Walt & Smith, 2015, CC0) as the degree-6 polynomial fit
    // of Matt Zucker (shadertoy.com/view/WlfXRN, CC0); it stays within about 0.01 of the
    // 256-entry table.
    t = t > 0 ? std::min(t, 1.0) : 0.0;
    constexpr double c[7][3] = {
        {0.0002189403691192265, 0.001651004631001012, -0.01948089843709184},
        {0.1065134194856116, 0.5639564367884091, 3.932712388889277},
        {11.60249308247187, -3.972853965665698, -15.9423941062914},
        {-41.70399613139459, 17.43639888205313, 44.35414519872813},
        {77.162935699427, -33.40235894210092, -81.80730925738993},
        {-71.31942824499214, 32.62606426397723, 73.20951985803202},
        {25.13112622477341, -12.24266895238567, -23.07032500287172},
    };
    double rgb[3];
    for (int k = 0; k < 3; ++k) {
        double v = c[6][k];
        for (int i = 5; i >= 0; --i) v = v * t + c[i][k];
        rgb[k] = std::clamp(v, 0.0, 1.0);
    }
    return {rgb[0], rgb[1], rgb[2]};
}

}  // namespace lenslab
