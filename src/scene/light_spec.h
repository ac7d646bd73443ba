#pragma once
// The declarations of the lights without geometry (light.h). `color` or `spectrum`, not
// both, is a rule between fields left to the reading code (spectral_json.h).

#include "scene/param_spec.h"

namespace lenslab {

const ElementSpec& point_light_spec();
const ElementSpec& beam_spec();

}  // namespace lenslab
