#pragma once
// Lens surfaces in scene files: `{"shape": "sphere", ...}` (docs/scene-format.md,
// "Surfaces"): the shape's entry in surface_shapes.h's table declares and reads its keys;
// here, the keys no shape takes and a shape's foreign keys are refused.

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geometry/lens/lens_surface.h"
#include "scene/param_spec.h"

namespace lenslab {

// Each shape's declaration ("sphere surface": `shape` and the shape's own keys); the shapes
// themselves are surface_shapes.h's table. The one for `shape`, or null.
const ElementSpec* surface_spec(const std::string& shape);
const ElementSpec& flat_surface_spec();
const ElementSpec& sphere_surface_spec();
const ElementSpec& conic_surface_spec();
const ElementSpec& asphere_surface_spec();
const ElementSpec& sag_surface_spec();

// Builds the surface described by `j` (at JSON path `path`) for a lens of the given
// semi-diameter (which sets a typed formula's finite-difference step). Throws SceneError:
// unknown shape, a key the shape does not take, a zero radius, bad coefficients, a formula
// that does not parse. Whether the surface fits the lens is the lens's check.
std::shared_ptr<const LensSurface> read_lens_surface(const nlohmann::json& j,
                                                     const std::string& path, double semi_diameter);

}  // namespace lenslab
