#pragma once
// The kinds of light a scene's `lights` may hold, one entry each: the `type` string, its
// declaration (the keys it takes) and the reader that adds it to the scene's lights. A new
// kind is one file that declares, reads and builds it (rectangle_light.cpp is one) and one
// line in light_types.cpp's table; the scene reader, the "unknown light type" message, the
// editor's "Add light" menu and form, `lenslab types`, Python's lenslab.light_types() and the
// docs' test all read this table.

#include <string>
#include <vector>

#include "scene/light.h"
#include "scene/param_spec.h"
#include "scene/spec_reader.h"

namespace lenslab {

struct LightTypeEntry {
    std::string name;  // the `type` string
    const ElementSpec& (*spec)() = nullptr;
    // Reads one light through a SpecReader made from `spec` and adds it to `lights`.
    void (*read)(SpecReader& r, SceneLights& lights) = nullptr;
};

// Every kind, in the order the "known:" list gives them.
const std::vector<LightTypeEntry>& light_types();
// The entry for `name`, or null.
const LightTypeEntry* find_light_type(const std::string& name);

}  // namespace lenslab
