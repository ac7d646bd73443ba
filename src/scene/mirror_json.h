#pragma once
// The `mirror` object of scene files (docs/scene-format.md, "Mirror"): one lens surface of any
// shape standing alone, with its diameter and an optional central hole.

#include <memory>

#include "geometry/lens/lens_surface.h"
#include "geometry/shape.h"
#include "scene/spec_reader.h"

namespace lenslab {

const ElementSpec& mirror_spec();

// `r` reads through mirror_spec(). Throws SceneError naming the key at fault.
std::shared_ptr<const Shape> read_mirror(SpecReader& r);

// Refuses, at `path`, a mirror surface that cannot span the diameter or whose typed formula
// is undefined somewhere on the disc (it would render with holes). A lens group's mirror
// elements are checked the same way.
void check_mirror_surface(const LensSurface& surface, double diameter, const std::string& path);

}  // namespace lenslab
