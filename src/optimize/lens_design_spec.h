#pragma once
// The optimiser's design file declared once (docs/optimizer.md): its top-level keys with their
// kinds, defaults and ranges, and for each type of variable and operand the keys it takes.
// The design reader, `lenslab optimize --iterations` and the docs' tables follow from these
// (tests/optimize/test_lens_design_spec.cpp holds the tables to them).

#include <string>
#include <vector>

#include "optimize/design_variable.h"
#include "optimize/lens_design.h"
#include "optimize/merit_operand.h"
#include "scene/json_reader.h"
#include "scene/param_spec.h"

namespace lenslab {

// The file's top-level keys (the `system`, `variables`, `operands` and `glass_choices`
// entries are read by their own code).
const ElementSpec& lens_design_spec();
// The `tolerances` block's keys.
const ElementSpec& tolerances_spec();
// An entry of `configurations` (design_configurations.h).
const ElementSpec& configuration_spec();
// The `global_search` block's keys.
const ElementSpec& global_search_spec();
// The `glass_substitution` block's keys.
const ElementSpec& glass_substitution_spec();

// A type of `variables` or `operands` entry: its `type` name and the keys it takes besides
// `type`, in the docs' order.
template <class Kind>
struct DesignEntryType {
    std::string type;
    Kind kind;
    std::vector<std::string> keys;
};

const std::vector<DesignEntryType<VariableKind>>& variable_types();
const std::vector<DesignEntryType<OperandKind>>& operand_types();

// The keys any type of entry takes, with `type`: what a JsonObjectReader of an entry allows.
template <class Kind>
std::vector<std::string> entry_keys(const std::vector<DesignEntryType<Kind>>& types);

// Reads `entry`'s `type` (required, one of `types`) through its `reader` and refuses any key
// its type does not take ("a thickness variable takes no surface (it takes lens)"); `noun`
// is "variable" or "operand".
template <class Kind>
const DesignEntryType<Kind>& read_entry_type(const nlohmann::json& entry, JsonObjectReader& reader,
                                             const std::vector<DesignEntryType<Kind>>& types,
                                             const std::string& noun);

}  // namespace lenslab
