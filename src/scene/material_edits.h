#pragma once
// Edits of a scene's named materials: the "materials" table and every object (or lens-group
// element) that names one with "material": "NAME". Each takes the scene document as JSON and
// returns the edited document, whole, so the editor applies it as one undoable step; a
// refused edit throws MaterialEditError with the reason, and the input is never changed.

#include <nlohmann/json_fwd.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace lenslab {

struct MaterialEditError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// JSON pointers of the "material" keys that name `name` ("/objects/2/material",
// "/objects/4/elements/1/material"), in document order.
std::vector<std::string> material_users(const nlohmann::json& scene, const std::string& name);

// `wanted`, or "wanted 2" (3, ...) when the table has that name already.
std::string unused_material_name(const nlohmann::json& scene, const std::string& wanted);

// A new grey diffuse material named after `wanted` (made unique); its name in `*added`.
nlohmann::json add_material(const nlohmann::json& scene, const std::string& wanted,
                            std::string* added);

// Renames `from` to `to` and every use with it. Refused: `to` empty or taken, `from` unknown.
nlohmann::json rename_material(const nlohmann::json& scene, const std::string& from,
                               const std::string& to);

// A copy of `name` as "NAME copy" (made unique); its name in `*added`.
nlohmann::json duplicate_material(const nlohmann::json& scene, const std::string& name,
                                  std::string* added);

// Removes `name`. Refused while anything uses it, naming the users, unless `replacement`
// (another material of the table) is given: then its users take that one.
nlohmann::json delete_material(const nlohmann::json& scene, const std::string& name,
                               const std::string& replacement = "");

// The use at `reference` (a pointer from material_users) gets a copy of its material of its
// own, "NAME 2" or the next free name, so editing it changes nothing else; its name in
// `*added`. Refused when `reference` does not name a material of the table.
nlohmann::json make_material_unique(const nlohmann::json& scene, const std::string& reference,
                                    std::string* added);

}  // namespace lenslab
