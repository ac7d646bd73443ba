#pragma once
// The scene's tone map (image/tone_map.h): its render block's `tone_map` and
// `highlight_stops`, with an exposure (the command line's --exposure).

#include "image/tone_map.h"
#include "scene/render_settings.h"

namespace lenslab {

inline ToneMap tone_map_for(const RenderSettings& render, double exposure_stops = 0) {
    return {exposure_stops, render.tone_map == ToneMapCurve::Log, render.highlight_stops};
}

}  // namespace lenslab
