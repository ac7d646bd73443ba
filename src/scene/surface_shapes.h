#pragma once
// The shapes a lens face may take (a surface's `"shape"`), one entry each: the name, its
// declaration (the keys it takes, with an example), the reader that builds it and what a face
// switched to it in the editor becomes. A new shape is one file that declares and reads it
// (biconic_surface_shape.cpp is one) and one line in surface_shapes.cpp's table; the scene
// reader, the "unknown surface shape" message, the editor's shape choice and form,
// `lenslab types`, Python's lenslab.types() and the docs' test all read this table.

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geometry/lens/lens_surface.h"
#include "scene/param_spec.h"
#include "scene/spec_reader.h"

namespace lenslab {

struct SurfaceShapeEntry {
    std::string name;  // the `shape` string
    // Its declaration, named "NAME surface"; its example is a valid surface of this shape.
    const ElementSpec& (*spec)() = nullptr;
    // Builds the surface through a SpecReader made from `spec`, for a lens of this
    // semi-diameter (which sets a typed formula's finite-difference step).
    std::shared_ptr<const LensSurface> (*read)(SpecReader& r, double semi_diameter) = nullptr;
    // What a face of `diameter` switched to this shape becomes, keeping what carries over from
    // `old` (an object: radius, k, coefficients); a new radius is twice the diameter.
    nlohmann::json (*start)(const nlohmann::json& old, double diameter) = nullptr;
    // For a shape with a formula key: why its text would be refused, or nothing (the
    // editor's formula field checks as the user types).
    std::optional<std::string> (*check_formula)(const std::string& text) = nullptr;
};

// Every shape, in the order the documentation and the editor list them.
const std::vector<SurfaceShapeEntry>& surface_shapes();
// The entry for `name`, or null.
const SurfaceShapeEntry* find_surface_shape(const std::string& name);

}  // namespace lenslab
