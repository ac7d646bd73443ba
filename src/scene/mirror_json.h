#pragma once
// The `mirror` object of scene files (docs/scene-format.md, "Mirror"): one lens surface of any
// shape standing alone, with its diameter and an optional central hole.

#include <memory>

#include "geometry/shape.h"
#include "scene/spec_reader.h"

namespace lenslab {

const ElementSpec& mirror_spec();

// `r` reads through mirror_spec(). Throws SceneError naming the key at fault.
std::shared_ptr<const Shape> read_mirror(SpecReader& r);

}  // namespace lenslab
