#pragma once
// The declaration of the scene file's `render` block (render_settings.h): what the reader,
// `lenslab render`'s overrides, the editor's form and the docs table all follow.

#include "scene/param_spec.h"

namespace lenslab {

const ElementSpec& render_settings_spec();

}  // namespace lenslab
