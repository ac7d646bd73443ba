#pragma once
// The kinds of object a scene's `objects` may hold, one entry each (object_types.cpp): the
// `type` string, the ObjectType it becomes, its declaration (the keys it takes), the function
// that builds its shape, and the rules that differ between kinds. The scene reader, the "unknown
// object type" message and the editor's fallback form all read this table.

#include <memory>
#include <string>
#include <vector>

#include "geometry/shape.h"
#include "scene/json_reader.h"
#include "scene/param_spec.h"
#include "scene/scene.h"
#include "scene/spec_reader.h"

namespace lenslab {

struct ObjectTypeEntry {
    std::string name;  // the `type` string
    ObjectType type;
    // The declaration the object is read through (a SpecReader): every kind has one.
    const ElementSpec& (*spec)() = nullptr;
    // Builds the shape; `r` is the SpecReader made from `spec`. Null for lens_group, which
    // scene_from_json reads itself (it makes one object per element).
    std::shared_ptr<const Shape> (*read)(SpecReader& r, const std::string& base_dir) = nullptr;
    // May take `detector` (flat shapes): the key that sets its size ("radius"), else null.
    const char* detector_size_key = nullptr;
    bool may_emit = false;         // its material may have an emission
    bool open_mesh_check = false;  // refuse an open mesh with a transparent material
};

// Every kind, in the order the "known:" list gives them.
const std::vector<ObjectTypeEntry>& object_types();
// The entry for `name`, or null.
const ObjectTypeEntry* find_object_type(const std::string& name);
// "unknown object type 'x' (known: ...; did you mean '...'?)".
std::string unknown_object_type_message(const std::string& name);

}  // namespace lenslab
