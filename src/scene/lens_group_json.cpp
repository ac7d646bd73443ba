#include "scene/lens_group_json.h"

#include <memory>

#include "geometry/lens/lens_solid.h"
#include "scene/json_reader.h"
#include "scene/limits.h"
#include "scene/surface_json.h"

namespace lenslab {

namespace {

using nlohmann::json;

struct ElementSpec {
    std::string path, name;
    double thickness = 0, gap = 0, diameter = 0;
    const json* front = nullptr;
    const json* back = nullptr;  // nullptr: cemented to the next element's front
    int material = 0;
};

}  // namespace

const std::vector<std::string>& lens_group_keys() {
    static const std::vector<std::string> keys{"vertex", "axis", "diameter", "x_axis", "elements"};
    return keys;
}

std::vector<SceneObject> read_lens_group(const json& j, const std::string& path,
                                         const MaterialResolver& material) {
    std::vector<std::string> keys{"type", "name", "photon_target"};
    keys.insert(keys.end(), lens_group_keys().begin(), lens_group_keys().end());
    JsonObjectReader r(j, path, keys, "a lens group");
    const std::string name = r.string("name", path);
    const std::optional<bool> photon_target = r.boolean("photon_target");
    const Vec3 vertex = r.vec3("vertex");
    const Vec3 axis = r.direction("axis");
    const double group_diameter = r.positive("diameter");
    const Vec3 x_axis = r.has("x_axis") ? r.direction("x_axis") : Vec3{};

    const json& list = r.require("elements");
    const std::string list_path = r.child_path("elements");
    if (!list.is_array() || list.empty()) {
        throw SceneError(list_path, "must be a non-empty array of elements, front to back");
    }
    check_count(list.size(), kMaxObjects, list_path, "elements");
    std::vector<ElementSpec> specs(list.size());
    for (size_t i = 0; i < list.size(); ++i) {
        ElementSpec& e = specs[i];
        e.path = list_path + "[" + std::to_string(i) + "]";
        JsonObjectReader er(list[i], e.path,
                            {"name", "front", "back", "thickness", "gap", "diameter", "material"},
                            "a lens group element");
        e.name = er.string("name", name + " element " + std::to_string(i + 1));
        e.thickness = er.positive("thickness");
        e.gap = er.has("gap") ? er.number("gap") : 0.0;
        if (e.gap < 0)
            throw SceneError(er.child_path("gap"),
                             "must be >= 0 (the air space after the element)");
        e.diameter = er.positive("diameter", group_diameter);
        e.front = &er.require("front");
        e.back = er.find("back");
        const bool last = i + 1 == list.size();
        if (!e.back && (last || e.gap > 0)) {
            throw SceneError(e.path,
                             last ? "the last element needs a back surface"
                                  : "an element followed by an air gap needs a back surface");
        }
        if (e.back && !last && e.gap == 0) {
            throw SceneError(er.child_path("back"),
                             "an element with no gap after it is cemented: its back is the next "
                             "element's front (give a gap, or leave out back)");
        }
        e.material = material(er, e.name);
    }

    std::vector<SceneObject> objects;
    double z = 0;  // axial position of the current element's front vertex
    for (size_t i = 0; i < specs.size(); ++i) {
        const ElementSpec& e = specs[i];
        const json& back = e.back ? *e.back : *specs[i + 1].front;
        const std::string back_path = e.back ? e.path + ".back" : specs[i + 1].path + ".front";
        LensPrescription p;
        p.centre = vertex + axis * (z + 0.5 * e.thickness);
        p.axis = axis;
        p.thickness = e.thickness;
        p.diameter = e.diameter;
        p.front = read_lens_surface(*e.front, e.path + ".front", 0.5 * e.diameter);
        p.back = read_lens_surface(back, back_path, 0.5 * e.diameter);
        p.x_axis = x_axis;
        if (auto problem = LensSolid::check_prescription(p)) {
            const std::string field = problem->field == "back"     ? back_path
                                      : problem->field == "front"  ? e.path + ".front"
                                      : problem->field == "x_axis" ? r.child_path("x_axis")
                                                                   : e.path + "." + problem->field;
            throw SceneError(field, problem->reason);
        }
        SceneObject o;
        o.name = e.name;
        o.group = name;
        o.type = ObjectType::Lens;
        o.shape = std::make_shared<LensSolid>(std::move(p));
        o.material = e.material;
        o.photon_target = photon_target;
        objects.push_back(std::move(o));
        z += e.thickness + e.gap;
    }
    return objects;
}

}  // namespace lenslab
