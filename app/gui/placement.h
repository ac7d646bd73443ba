#pragma once
// Where a new or placed object goes: resting on the first surface a ray from the eye meets,
// on the side the eye sees, touching it with its bounding box (not inside what is there).

#include <optional>

#include "scene/scene.h"

namespace lenslab::gui {

// How far a thing whose box is `box` must move to rest on what `ray` meets first; nothing
// when the ray meets nothing. The scene entry `ignore` (the thing itself, when it is in the
// scene already) is looked through.
std::optional<Vec3> resting_offset(const Scene& scene, const Aabb& box, const Ray& ray,
                                   int ignore = -1);

// The box of the shapes scene entry `source` made (empty when none).
Aabb entry_bounds(const Scene& scene, int source);

}  // namespace lenslab::gui
