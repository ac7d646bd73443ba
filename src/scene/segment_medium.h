#pragma once
// Which participating medium (scene/medium.h) a stretch of a ray crosses: the tracers ask it
// for each segment between two surfaces, so fog, smoke and milky water are found the same way
// by the path tracer, the photon tracers and the detectors.

#include "scene/interaction.h"
#include "scene/medium.h"
#include "scene/scene.h"

namespace lenslab {

// The medium between `ray`'s origin and the surface `hit` (nullptr: the ray leaves the
// scene), or nullptr where the segment is clear. A segment ending at the back of a surface
// lies inside that solid; any other lies outside the objects, in the scene's atmosphere.
const Medium* segment_medium(const Scene& scene, const Ray& ray, const Interaction* hit);

// Whether any segment can cross a medium (tracers skip the question otherwise).
bool has_media(const Scene& scene);

}  // namespace lenslab
