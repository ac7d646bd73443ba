#pragma once
// The object and light types a scene may hold and the shapes a lens surface may take, each
// with the keys it takes (besides `type` or `shape`), from the type tables (object_types.h,
// light_types.h, surface_shapes.h): `lenslab types` and Python's lenslab.types() print it, so
// a new type or shape lists itself.
// {"objects": [{"type": "sphere", "keys": [...]}, ...], "lights": [...], "surfaces": [...]}

#include <nlohmann/json.hpp>

namespace lenslab {

nlohmann::ordered_json scene_types_json();

}  // namespace lenslab
