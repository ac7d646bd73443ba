#pragma once
// The declarations of a material (material.h) and of its `emission` block. Which of `ior`
// and `glass` is given, and transparency + specular <= 1, are rules between fields, left to
// the reading code; a dispersion model (`ior` as an object) is read by spectral_json.

#include "scene/param_spec.h"

namespace lenslab {

const ElementSpec& material_spec();
const ElementSpec& emission_spec();
// The `grin` block of a transparent material: a gradient index (optics/grin_profile.h).
const ElementSpec& grin_spec();

}  // namespace lenslab
