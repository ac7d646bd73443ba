#pragma once
// The declarations of the lights without geometry (light.h). `color` or `spectrum`, not
// both, is a rule between fields left to the reading code (spectral_json.h).

#include <string>
#include <vector>

#include "optics/rgb.h"
#include "scene/param_spec.h"

namespace lenslab {

const ElementSpec& point_light_spec();
const ElementSpec& beam_spec();
const ElementSpec& laser_spec();
const ElementSpec& spot_light_spec();
// What every light takes besides where it is: power, color, spectrum.
std::vector<ParamSpec> light_emission_params(const Rgb& colour,
                                             std::string power_meaning = "radiant flux (W)");
// From the table of light_types.h:
// the declaration of the light whose `type` is `type` ("point", "beam", ...), or null.
const ElementSpec* find_light_spec(const std::string& type);
// Every light type's declaration, in the order "known:" lists them.
const std::vector<const ElementSpec*>& light_specs();

}  // namespace lenslab
