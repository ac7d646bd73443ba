#pragma once
// Which participating medium (scene/medium.h) a stretch of a ray crosses: the tracers ask it
// for each segment between two surfaces, so fog, smoke and milky water are found the same way
// by the path tracer, the photon tracers and the detectors.

#include "scene/interaction.h"
#include "scene/medium.h"
#include "scene/scene.h"

namespace lenslab {

// The medium between `ray`'s origin and the surface `hit` (nullptr: the ray leaves the
// scene), or nullptr where the segment is clear. A segment ending at the back of a closed
// surface lies inside that solid: its medium, or none (clear glass). Any other lies in the
// innermost medium-holding solid around it (medium_at at the segment's middle), else in the
// scene's atmosphere; a ray leaving the scene is inside no solid.
const Medium* segment_medium(const Scene& scene, const Ray& ray, const Interaction* hit);

// The medium at `point`: that of the innermost solid holding a medium that contains it, else
// the atmosphere; nullptr where that is clear.
const Medium* medium_at(const Scene& scene, const Vec3& point);

}  // namespace lenslab
