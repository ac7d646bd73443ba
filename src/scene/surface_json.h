#pragma once
// Lens surfaces in scene files: `{"shape": "flat" | "sphere" | "conic" | "asphere" | "sag",
// ...}` (docs/scene-format.md, "Surfaces"). Kept apart from scene_json.cpp because every
// shape has its own keys (declared here, one ElementSpec per shape) and checks.

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geometry/lens/lens_surface.h"
#include "scene/param_spec.h"

namespace lenslab {

// The shapes a lens face can take, in the order the documentation and the editor list them.
extern const std::vector<std::string> kSurfaceShapeNames;

// Each shape's declaration ("sphere surface": `shape` and the shape's own keys), in the order
// of kSurfaceShapeNames; the one for `shape`, or null.
const std::vector<ElementSpec>& surface_specs();
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
