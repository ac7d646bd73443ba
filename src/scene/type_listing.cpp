#include "scene/type_listing.h"

#include "scene/light_types.h"
#include "scene/object_types.h"
#include "scene/surface_shapes.h"

namespace lenslab {

namespace {

nlohmann::ordered_json type_row(const std::string& name, const ElementSpec& spec) {
    nlohmann::ordered_json keys = nlohmann::ordered_json::array();
    for (const std::string& k : spec.keys()) {
        if (k != "type") keys.push_back(k);
    }
    return {{"type", name}, {"keys", keys}};
}

}  // namespace

nlohmann::ordered_json scene_types_json() {
    nlohmann::ordered_json out;
    out["objects"] = nlohmann::ordered_json::array();
    for (const ObjectTypeEntry& e : object_types())
        out["objects"].push_back(type_row(e.name, e.spec()));
    out["lights"] = nlohmann::ordered_json::array();
    for (const LightTypeEntry& e : light_types())
        out["lights"].push_back(type_row(e.name, e.spec()));
    out["surfaces"] = nlohmann::ordered_json::array();
    for (const SurfaceShapeEntry& e : surface_shapes()) {
        nlohmann::ordered_json row = type_row(e.name, e.spec());
        row["keys"].erase(0);  // "shape", which the row's type already names
        out["surfaces"].push_back(std::move(row));
    }
    return out;
}

}  // namespace lenslab
