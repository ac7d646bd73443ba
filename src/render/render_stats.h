#pragma once
// What an integrator reports about its work, as plain data: the command line and the editor
// show it without knowing which integrator ran.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab {

struct RenderStat {
    std::string name;  // snake_case, e.g. "mean_radius"
    double value = 0;
};

struct RenderStats {
    // Passes run when the image was built pass by pass (render.passes, render.time); 0 when
    // it came from render.spp samples per pixel.
    int passes = 0;
    // The photons behind the image, for a status line: emitted so far (sppm), stored in the
    // maps (photon_map); 0 without photons.
    int64_t photons = 0;
    std::vector<RenderStat> values;  // everything else the integrator measured
    std::string summary;             // one line for a log, formatted by the integrator; "": none

    // The value called `name`; throws std::out_of_range when there is none.
    double value(std::string_view name) const;
};

}  // namespace lenslab
