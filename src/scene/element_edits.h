#pragma once
// Edits of a scene's objects and lights as the editor's Add, Duplicate, Delete, Add floor and
// Add atmosphere make them. Each takes the scene document as JSON and returns the edited
// document, whole, with the JSON pointer of the element to select, so the editor applies it as
// one undoable step; the input is never changed. No Qt: tests/scene/test_element_edits.cpp.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "math/vec3.h"
#include "scene/param_spec.h"

namespace lenslab {

class Scene;

// The declaration of an element of `list` ("objects", "lights") with this `type`, or null.
const ElementSpec* element_spec(const std::string& list, const std::string& type);

// The list an element of `type` belongs to: "lights" for a light's type, else "objects".
std::string element_list(const std::string& type);

// `wanted` ("sphere"), or "sphere 2" (3, ...) when an object of the scene has that name already.
std::string unique_object_name(const nlohmann::json& scene, const std::string& wanted);

// `element` of `list`, moved by `offset` (through its declaration) and named uniquely, ready
// to append to the scene.
nlohmann::json placed_element(const nlohmann::json& scene, const std::string& list,
                              nlohmann::json element, const Vec3& offset);

struct ElementEdit {
    nlohmann::json scene;  // the edited document
    // What to select after the edit: the element it added ("/objects/3"); after a removal,
    // the one that took its place, or the one before it at the end of its list; "" when
    // none is left (or the atmosphere went).
    std::string pointer;
};

// `element` appended to `list` (the list made when the scene has none).
ElementEdit with_element(const nlohmann::json& scene, const std::string& list,
                         nlohmann::json element);

// A copy of the object or light at `pointer` ("/objects/2", "/lights/0"), named "NAME copy"
// (made unique) and moved 0.5 along x; nullopt when `pointer` is no object or light.
std::optional<ElementEdit> with_duplicate(const nlohmann::json& scene, const std::string& pointer);

// The object or light at `pointer` removed, or the atmosphere for "/atmosphere"; nullopt when
// `pointer` names nothing of these.
std::optional<ElementEdit> without_element(const nlohmann::json& scene, const std::string& pointer);

// A floor: a thin box (one object, not triangles) under everything `built` (the document
// read) holds, its top where the lowest object ends (y is up, as the camera's default), four
// times as wide as the scene so its edges stay out of most views; 10 wide at y = 0 in an empty
// scene.
nlohmann::json floor_under(const Scene& built, const nlohmann::json& scene);

// Volume photons' neighbours an added atmosphere renders with: each sparse photon's disc grows
// until this many share it, so the veil of a room's lamps is a smooth glow and a faint beam
// (a 0.1 W laser beside the default scene's lamp) shows through it in seconds, not under
// snow-like specks of single photons.
inline constexpr int kAtmosphereVolumeNeighbours = 16;

// The declared atmosphere's example, when the scene has no atmosphere yet, and the render's
// volume_neighbours set to kAtmosphereVolumeNeighbours unless the scene chose one.
nlohmann::json with_atmosphere(const nlohmann::json& scene);

}  // namespace lenslab
