#include "scene/element_edits.h"

#include <algorithm>
#include <set>

#include "scene/light_spec.h"
#include "scene/medium.h"
#include "scene/object_types.h"
#include "scene/scene.h"

namespace lenslab {

using nlohmann::json;

namespace {

bool is_element_pointer(const std::string& pointer) {
    for (const char* list : {"/objects/", "/lights/"}) {
        const std::string prefix = list;
        if (pointer.size() > prefix.size() && pointer.compare(0, prefix.size(), prefix) == 0 &&
            pointer.find_first_not_of("0123456789", prefix.size()) == std::string::npos)
            return true;
    }
    return false;
}

// "objects" and 3 of "/objects/3".
std::pair<std::string, size_t> list_and_index(const std::string& pointer) {
    const size_t slash = pointer.find('/', 1);
    return {pointer.substr(1, slash - 1), std::stoul(pointer.substr(slash + 1))};
}

std::string pointer_to(const std::string& list, size_t index) {
    return "/" + list + "/" + std::to_string(index);
}

}  // namespace

const ElementSpec* element_spec(const std::string& list, const std::string& type) {
    if (list == "lights") return find_light_spec(type);
    const ObjectTypeEntry* kind = find_object_type(type);
    return kind ? &kind->spec() : nullptr;
}

std::string element_list(const std::string& type) {
    return find_light_spec(type) ? "lights" : "objects";
}

std::string unique_object_name(const json& scene, const std::string& wanted) {
    std::set<std::string> taken;
    if (scene.contains("objects") && scene["objects"].is_array()) {
        for (const json& o : scene["objects"]) {
            if (o.is_object() && o.contains("name") && o["name"].is_string())
                taken.insert(o["name"].get<std::string>());
        }
    }
    std::string name = wanted;
    for (int n = 2; taken.count(name); ++n) name = wanted + " " + std::to_string(n);
    return name;
}

json placed_element(const json& scene, const std::string& list, json element, const Vec3& offset) {
    if (const ElementSpec* spec = element_spec(list, element.value("type", "")))
        element = moved_element(*spec, std::move(element), offset);
    if (element.contains("name") && element["name"].is_string())
        element["name"] = unique_object_name(scene, element["name"].get<std::string>());
    return element;
}

ElementEdit with_element(const json& scene, const std::string& list, json element) {
    ElementEdit edit{scene, ""};
    if (!edit.scene.contains(list) || !edit.scene[list].is_array())
        edit.scene[list] = json::array();
    edit.scene[list].push_back(std::move(element));
    edit.pointer = pointer_to(list, edit.scene[list].size() - 1);
    return edit;
}

std::optional<ElementEdit> with_duplicate(const json& scene, const std::string& pointer) {
    if (!is_element_pointer(pointer)) return std::nullopt;
    const json::json_pointer at(pointer);
    if (!scene.contains(at)) return std::nullopt;
    json copy = scene[at];
    if (copy.contains("name") && copy["name"].is_string())
        copy["name"] = copy["name"].get<std::string>() + " copy";
    const std::string list = list_and_index(pointer).first;
    return with_element(scene, list, placed_element(scene, list, std::move(copy), {0.5, 0, 0}));
}

std::optional<ElementEdit> without_element(const json& scene, const std::string& pointer) {
    ElementEdit edit{scene, ""};
    if (pointer == "/atmosphere") {
        if (!edit.scene.erase("atmosphere")) return std::nullopt;
        return edit;
    }
    if (!is_element_pointer(pointer)) return std::nullopt;
    const auto [list, index] = list_and_index(pointer);
    if (!edit.scene.contains(list) || !edit.scene[list].is_array() ||
        index >= edit.scene[list].size())
        return std::nullopt;
    edit.scene[list].erase(index);
    const size_t left = edit.scene[list].size();
    if (left > 0)
        edit.pointer = "/" + list + "/" + std::to_string(std::min<size_t>(index, left - 1));
    return edit;
}

json floor_under(const Scene& built, const json& scene) {
    const Aabb box = built.bounds();
    const Vec3 centre = box.empty() ? Vec3{0, 0, 0} : box.centre();
    const Vec3 extent = box.empty() ? Vec3{0, 0, 0} : box.extent();
    const double widest = std::max({extent.x, extent.y, extent.z});
    const double side = widest > 0 ? 4 * widest : 10.0;
    const double thickness = side / 100;
    const double top = box.empty() ? 0.0 : box.lo.y;
    return json{{"type", "box"},
                {"name", unique_object_name(scene, "floor")},
                {"center", {centre.x, top - thickness / 2, centre.z}},
                {"size", {side, thickness, side}},
                {"material", {{"color", 0.7}}}};
}

json with_atmosphere(const json& scene) {
    json edited = scene;
    if (edited.contains("atmosphere")) return edited;
    edited["atmosphere"] = medium_spec().example;
    json& render = edited["render"];
    if (render.is_null()) render = json::object();
    if (render.value("volume_neighbours", 0) == 0) {
        render["volume_neighbours"] = kAtmosphereVolumeNeighbours;
    }
    return edited;
}

}  // namespace lenslab
