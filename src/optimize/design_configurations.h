#pragma once
// Multi-configuration designs (docs/optimizer.md#configurations): a zoom lens's focal lengths,
// say, optimised together. The design's `configurations` each set air gaps, fields and an image
// plane; every operand of the design is evaluated in each configuration, beside the
// configuration's own; a variable with a `configuration` belongs to that configuration alone
// (a zoom's air gaps, its image distance), the others are shared (the radii, the glasses).

#include <nlohmann/json.hpp>
#include <string>

#include "optimize/lens_design.h"

namespace lenslab {

// Reads `configurations` (an array) into d.configurations: their names, fields, image planes
// and air gaps. The operands come after (read_configuration_operands). Throws SceneError
// naming the JSON path.
void read_configurations(const nlohmann::json& list, LensDesign& d);

// A variable entry's `configuration` (an index or a name), removed from `spec` and written to
// `v`'s configuration once the variable is read; -1 where there is none.
int read_variable_configuration(nlohmann::json& spec, const std::string& path, const LensDesign& d);

// Refuses a shared variable of what a configuration sets (an air gap, the image distance):
// it would override the configuration's value.
void check_configuration_variable(const LensDesign& d, const DesignVariable& v);

// The operands of a multi-configuration design: each of `shared` (the design's `operands`)
// read for each configuration with its fields, then the configuration's own.
void read_configuration_operands(const nlohmann::json* shared, const nlohmann::json& list,
                                 LensDesign& d);

// Configuration k as a design of one configuration: its air gaps set in the scene, its fields
// and image plane, its operands, and the variables shared or of it alone, in the design's
// order (`globals`, where not null, gets each one's index in the design's variables).
LensDesign configuration_design(const LensDesign& d, int k, std::vector<int>* globals = nullptr);

}  // namespace lenslab
