// `lenslab types [--json]`: the object and light types a scene file may hold and the shapes
// of a lens surface, each with the keys it takes (scene/type_listing.h).

#include <iomanip>
#include <iostream>
#include <memory>

#include "commands.h"
#include "scene/type_listing.h"

namespace lenslab::cli {

Action add_types_command(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "types",
        "List the object and light types a scene file may hold, the shapes of a lens surface, "
        "and their keys");
    auto json = std::make_shared<bool>(false);
    cmd->add_flag("--json", *json,
                  "Print {\"objects\": [...], \"lights\": [...], \"surfaces\": [...]} as JSON");
    return [json] {
        const nlohmann::ordered_json types = scene_types_json();
        if (*json) {
            std::cout << types.dump(2) << "\n";
            return 0;
        }
        for (const char* list : {"objects", "lights", "surfaces"}) {
            std::cout << list << ":\n";
            for (const auto& row : types[list]) {
                std::string keys;
                for (const auto& k : row["keys"])
                    keys += (keys.empty() ? "" : ", ") + k.get<std::string>();
                std::cout << "  " << std::left << std::setw(16) << row["type"].get<std::string>()
                          << (keys.empty() ? "(no keys)" : keys) << "\n";
            }
        }
        std::cout << "(docs/scene-format.md describes each key)\n";
        return 0;
    };
}

}  // namespace lenslab::cli
