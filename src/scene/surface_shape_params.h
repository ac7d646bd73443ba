#pragma once
// What the lens surface shapes' files share: the parameters several shapes declare (the vertex
// radius, the conic constant, the even asphere's coefficients), reading them, and the radius
// a face keeps when the editor switches its shape.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/param_spec.h"
#include "scene/spec_reader.h"

namespace lenslab {

// "NAME surface": `shape` and then `own`, with `example` (a valid surface of the shape).
ElementSpec declare_surface_shape(const std::string& shape, std::vector<ParamSpec> own,
                                  nlohmann::json example);

ParamSpec vertex_radius_param();   // "radius", required, not 0
ParamSpec conic_constant_param();  // "k", default 0
// "coefficients": [A4, A6, ..., A16], `least` (0 or 1) to 7 of them.
ParamSpec asphere_coefficients_param(size_t least, std::string doc, std::string label);

// The radius, refused when 0 (a plane is the flat shape).
double read_vertex_radius(SpecReader& r);
// An array of numbers declared with holding_numbers(least, most) (empty when absent and may
// be empty); a refusal says "must be an array of LEAST to MOST numbers" + `what`.
std::vector<double> read_number_array(SpecReader& r, const std::string& key,
                                      const std::string& what = "");

// The radius a face switched from `old` keeps: its own, or twice the diameter for a new one.
double kept_radius(const nlohmann::json& old, double diameter);
// `old`'s number at `key`, or `fallback`.
double kept_number(const nlohmann::json& old, const std::string& key, double fallback);

}  // namespace lenslab
