#include "scene/material_edits.h"

#include <nlohmann/json.hpp>

namespace lenslab {

namespace {

using nlohmann::json;

// RFC 6901: "~" and "/" inside a token are escaped.
std::string pointer_token(const std::string& key) {
    std::string out;
    for (char c : key) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

// Calls `visit(pointer, value)` for every "material" key under `value` naming a material.
template <class Visit>
void for_each_material_name(json& value, const std::string& pointer, const Visit& visit) {
    if (value.is_object()) {
        for (auto& [key, child] : value.items()) {
            const std::string here = pointer + "/" + pointer_token(key);
            if (key == "material" && child.is_string())
                visit(here, child);
            else
                for_each_material_name(child, here, visit);
        }
    } else if (value.is_array()) {
        for (size_t i = 0; i < value.size(); ++i)
            for_each_material_name(value[i], pointer + "/" + std::to_string(i), visit);
    }
}

// Every use of `name` in the objects, renamed to `to` (`to` empty: only listed).
std::vector<std::string> retarget_uses(json& scene, const std::string& name,
                                       const std::string& to) {
    std::vector<std::string> users;
    if (!scene.is_object() || !scene.contains("objects")) return users;
    for_each_material_name(scene["objects"], "/objects", [&](const std::string& p, json& v) {
        if (v.get<std::string>() != name) return;
        users.push_back(p);
        if (!to.empty()) v = to;
    });
    return users;
}

bool has_material(const json& scene, const std::string& name) {
    return scene.is_object() && scene.contains("materials") && scene["materials"].is_object() &&
           scene["materials"].contains(name);
}

void require_material(const json& scene, const std::string& name) {
    if (!has_material(scene, name))
        throw MaterialEditError("there is no material named '" + name + "'");
}

// "'lens'", "objects[3]": how a message names the object a use belongs to. (Built by
// appending: GCC 12 warns falsely, -Wrestrict, on "'" + name + "'".)
std::string user_name(const json& scene, const std::string& pointer) {
    const size_t first = pointer.find('/', 1), second = pointer.find('/', first + 1);
    const std::string index = pointer.substr(first + 1, second - first - 1);
    const json& object = scene["objects"][std::stoul(index)];
    std::string out;
    if (object.contains("name") && object["name"].is_string()) {
        out.append(1, '\'').append(object["name"].get<std::string>()).append(1, '\'');
    } else {
        out.append("objects[").append(index).append("]");
    }
    return out;
}

}  // namespace

std::vector<std::string> material_users(const json& scene, const std::string& name) {
    json copy = scene;
    return retarget_uses(copy, name, "");
}

std::string unused_material_name(const json& scene, const std::string& wanted) {
    std::string name = wanted;
    for (int n = 2; has_material(scene, name); ++n) name = wanted + " " + std::to_string(n);
    return name;
}

json add_material(const json& scene, const std::string& wanted, std::string* added) {
    json out = scene;
    const std::string name = unused_material_name(scene, wanted.empty() ? "material" : wanted);
    out["materials"][name] = {{"color", {0.8, 0.8, 0.8}}};
    if (added) *added = name;
    return out;
}

json rename_material(const json& scene, const std::string& from, const std::string& to) {
    require_material(scene, from);
    if (to.empty()) throw MaterialEditError("a material's name must not be empty");
    if (to == from) return scene;
    if (has_material(scene, to))
        throw MaterialEditError("a material named '" + to + "' exists already");
    json out = scene;
    out["materials"][to] = std::move(out["materials"][from]);
    out["materials"].erase(from);
    retarget_uses(out, from, to);
    return out;
}

json duplicate_material(const json& scene, const std::string& name, std::string* added) {
    require_material(scene, name);
    json out = scene;
    const std::string copy = unused_material_name(scene, name + " copy");
    out["materials"][copy] = scene["materials"][name];
    if (added) *added = copy;
    return out;
}

json delete_material(const json& scene, const std::string& name, const std::string& replacement) {
    require_material(scene, name);
    json out = scene;
    if (!replacement.empty()) {
        if (replacement == name) throw MaterialEditError("a material cannot replace itself");
        require_material(scene, replacement);
        retarget_uses(out, name, replacement);
    }
    const std::vector<std::string> users = retarget_uses(out, name, "");
    if (!users.empty()) {
        std::string who;
        for (size_t i = 0; i < users.size() && i < 3; ++i) {
            if (i) who += ", ";
            who += user_name(out, users[i]);
        }
        if (users.size() > 3) who += " and " + std::to_string(users.size() - 3) + " more";
        throw MaterialEditError("'" + name + "' is used by " + who +
                                ": give them another material first");
    }
    out["materials"].erase(name);
    return out;
}

json make_material_unique(const json& scene, const std::string& reference, std::string* added) {
    const json::json_pointer at(reference);
    if (!scene.contains(at) || !scene.at(at).is_string())
        throw MaterialEditError(reference + " does not name a material");
    const std::string name = scene.at(at).get<std::string>();
    require_material(scene, name);
    json out = scene;
    const std::string copy = unused_material_name(scene, name);
    out["materials"][copy] = scene["materials"][name];
    out[at] = copy;
    if (added) *added = copy;
    return out;
}

}  // namespace lenslab
