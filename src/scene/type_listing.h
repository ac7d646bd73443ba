#pragma once
// The object and light types a scene may hold, each with the keys it takes (besides `type`),
// from the type tables (object_types.h, light_types.h): `lenslab types` and Python's
// lenslab.types() print it, so a new type lists itself.
// {"objects": [{"type": "sphere", "keys": [...]}, ...], "lights": [...]}

#include <nlohmann/json.hpp>

namespace lenslab {

nlohmann::ordered_json scene_types_json();

}  // namespace lenslab
