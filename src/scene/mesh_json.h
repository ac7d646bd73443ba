#pragma once
// Scene objects made of triangles (docs/scene-format.md, "Mesh" and "Prism"). Their keys,
// defaults and ranges are declared in mesh_spec() and prism_spec() (mesh_json.cpp); the rules
// between keys (inline or OBJ form, perpendicular frames) stay with the readers.
//
// A closed mesh (every edge shared by two faces running along it in opposite directions) is
// a solid of its material; one given inside-out (negative signed volume) is turned outward.
// An open mesh is a set of two-sided triangles, accepted only with an opaque material.

#include <memory>
#include <string>
#include <vector>

#include "geometry/shape.h"
#include "scene/json_reader.h"
#include "scene/material.h"
#include "scene/param_spec.h"
#include "scene/spec_reader.h"

namespace lenslab {

// Their declarations: the common object keys (no detector) and their own.
const ElementSpec& mesh_spec();
const ElementSpec& prism_spec();

// Build the shape; errors name the JSON path. Relative OBJ paths are looked up in
// `base_dir` ("" = the current directory).
// `r` reads through mesh_spec() or prism_spec().
std::shared_ptr<const Shape> read_mesh(SpecReader& r, const std::string& base_dir);
std::shared_ptr<const Shape> read_prism(SpecReader& r);

// For `mesh` objects (a prism is closed by construction, or refused by read_prism).
// Refuses an open mesh with a transparent material: it would be a set of thin panes, not a
// solid, which is almost never what was meant.
void check_mesh_material(JsonObjectReader& r, const Shape& shape, const Material& material);

}  // namespace lenslab
