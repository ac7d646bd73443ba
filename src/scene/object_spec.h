#pragma once
// The declarations of what every object in `objects` takes, and of the shapes read through
// them (the sphere, the triangle and the implicit solid here; the disc and the rectangle in
// planar_json.h; the lens here too; the mesh and the prism in mesh_json.h, the box in box_json.h,
// the lens group in lens_group_json.h).

#include "scene/param_spec.h"

namespace lenslab {

// type, name, material, detector, photon_target: the docs' "Objects" table.
const ElementSpec& object_common_spec();
// The common keys a sphere takes (not `detector`) and its own.
const ElementSpec& sphere_spec();
const ElementSpec& implicit_spec();
const ElementSpec& triangle_spec();
// Both forms of a lens (report and prescription) in one declaration; the reader keeps them
// apart.
const ElementSpec& lens_spec();

// A shape's declaration to add its own keys to: the common ones (`detector` only for the
// flat shapes, which can measure light).
ElementSpec shape_spec(std::string name, std::string phrase, bool takes_detector);

// decenter_x, decenter_y, tilt_x, tilt_y and tilt_z (rigid_motion.h), for a lens group's
// element and a lens: `moved` says what moves with it and what stays.
void add_decentring_params(ElementSpec& s, const std::string& what, const std::string& moved);

// Whether `key` is one of the common keys (documented once, not under each shape).
bool is_common_object_key(const std::string& key);

}  // namespace lenslab
