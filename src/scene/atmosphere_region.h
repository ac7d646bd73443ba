#pragma once
// Where a heterogeneous atmosphere is: the box around everything in the scene that light
// starts from, crosses or ends at (objects, camera, lights), a little enlarged. Its density
// is sampled for a majorant over this box and taken as 0 outside it, so a ray leaving the
// scene crosses a finite amount of it.

#include "math/aabb.h"

namespace lenslab {

class Scene;

// Its lights() are the scene's lights (set_lights or build).
Aabb atmosphere_region(const Scene& scene);

}  // namespace lenslab
