#pragma once
// Scene objects made of triangles (docs/scene-format.md, "Mesh" and "Prism"):
//
// mesh   | vertices  | array of points         | inline vertices (with faces)
//        | faces     | array of index arrays   | 0-based; polygons are fan-triangulated
//        | file      | string                  | an OBJ file, relative to the scene's folder
//        | scale     | number > 0, default 1   | model units -> scene units
//        | up        | direction, [0, 1, 0]    | where the model's +y points
//        | facing    | direction, [0, 0, 1]    | where the model's +z points (perpendicular to up)
//        | position  | point, [0, 0, 0]        | where the model's origin goes
// prism  | apex_angle| degrees, (0, 180), 60   | angle between the refracting faces
//        | side      | number > 0, required    | length of the two faces meeting at the apex
//        | height    | number > 0, required    | length along axis
//        | center    | point, required         | centre of the bounding box
//        | axis      | direction, [0, 1, 0]    | the long axis (along the height)
//        | facing    | direction, [0, 0, 1]    | from the base towards the apex, perpendicular to
//        axis
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

namespace lenslab {

// Keys of each type besides type, name and material.
const std::vector<std::string>& mesh_keys();
const std::vector<std::string>& prism_keys();

// Build the shape; errors name the JSON path. Relative OBJ paths are looked up in
// `base_dir` ("" = the current directory).
std::shared_ptr<const Shape> read_mesh(JsonObjectReader& r, const std::string& base_dir);
std::shared_ptr<const Shape> read_prism(JsonObjectReader& r);

// For `mesh` objects (a prism is closed by construction, or refused by read_prism).
// Refuses an open mesh with a transparent material: it would be a set of thin panes, not a
// solid, which is almost never what was meant.
void check_mesh_material(JsonObjectReader& r, const Shape& shape, const Material& material);

}  // namespace lenslab
