#pragma once
// A lens group in scene files: elements on one axis, listed in the order light meets them as
// a lens designer's prescription table; an element with no air gap after it is cemented to
// the next, sharing its back face with the next element's front. A mirror element turns the
// light back along the axis: the elements after it lie the other way, their distances still
// counted the way light travels, every face signed along the group's axis
// (docs/scene-format.md, "Lens group"). It becomes one lens or mirror object per element.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/param_spec.h"
#include "scene/scene.h"

namespace lenslab {

class JsonObjectReader;

// Resolves an element's `material` (a name or an inline material) to an index into the
// scene's materials; given by the scene reader.
using MaterialResolver = std::function<int(JsonObjectReader& element, const std::string& owner)>;

// The declarations of a lens group (type, name and photon_target but not material, which
// each element names itself, and its own keys), of one of its lens elements and of a mirror.
const ElementSpec& lens_group_spec();
const ElementSpec& lens_group_element_spec();
const ElementSpec& lens_group_mirror_spec();

// Reads the lens group at JSON path `path`; throws SceneError.
std::vector<SceneObject> read_lens_group(const nlohmann::json& j, const std::string& path,
                                         const MaterialResolver& material);

}  // namespace lenslab
