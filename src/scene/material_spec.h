#pragma once
// The declarations of a material (material.h) and of its `emission` block. Which of `ior`
// and `glass` is given, and transparency + specular <= 1, are rules between fields, left to
// the reading code; a dispersion model (`ior` as an object) is read by spectral_json.

#include <string>
#include <vector>

#include "scene/param_spec.h"

namespace lenslab {

const ElementSpec& material_spec();
const ElementSpec& emission_spec();
// The `grin` block of a transparent material: a gradient index (optics/grin_profile.h).
const ElementSpec& grin_spec();
// The keys of the `grin` block that `profile` reads besides "profile" and "center", in the
// order the editor shows them; and the block the editor starts from when one picks it.
std::vector<std::string> grin_keys_of(const std::string& profile);
nlohmann::json grin_starting_block(const std::string& profile);

}  // namespace lenslab
