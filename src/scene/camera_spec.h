#pragma once
// The declaration of the scene file's `camera` (camera_settings.h). Which of look_at and
// direction is given is a rule between fields, left to the reading code.

#include "scene/param_spec.h"

namespace lenslab {

const ElementSpec& camera_spec();

}  // namespace lenslab
