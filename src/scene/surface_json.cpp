#include "scene/surface_json.h"

#include <algorithm>

#include "scene/json_reader.h"
#include "scene/spec_reader.h"
#include "scene/surface_shapes.h"

namespace lenslab {

namespace {

// Every key some shape takes.
std::vector<std::string> all_surface_keys() {
    std::vector<std::string> out;
    for (const SurfaceShapeEntry& e : surface_shapes()) {
        for (const std::string& key : e.spec().keys()) {
            if (std::find(out.begin(), out.end(), key) == out.end()) out.push_back(key);
        }
    }
    return out;
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::string shape_names() {
    std::vector<std::string> names;
    for (const SurfaceShapeEntry& e : surface_shapes()) names.push_back(e.name);
    return joined(names);
}

}  // namespace

const ElementSpec* surface_spec(const std::string& shape) {
    const SurfaceShapeEntry* e = find_surface_shape(shape);
    return e ? &e->spec() : nullptr;
}

const ElementSpec& flat_surface_spec() { return *surface_spec("flat"); }
const ElementSpec& sphere_surface_spec() { return *surface_spec("sphere"); }
const ElementSpec& conic_surface_spec() { return *surface_spec("conic"); }
const ElementSpec& asphere_surface_spec() { return *surface_spec("asphere"); }
const ElementSpec& sag_surface_spec() { return *surface_spec("sag"); }

std::shared_ptr<const LensSurface> read_lens_surface(const nlohmann::json& j,
                                                     const std::string& path,
                                                     double semi_diameter) {
    static const std::vector<std::string> any_shape = all_surface_keys();
    JsonObjectReader any(j, path, any_shape);
    const std::string shape = any.string("shape");
    const SurfaceShapeEntry* entry = find_surface_shape(shape);
    if (!entry) {
        throw SceneError(any.child_path("shape"),
                         "unknown surface shape '" + shape + "' (known: " + shape_names() + ")");
    }
    const ElementSpec& spec = entry->spec();
    std::vector<std::string> takes = spec.keys();
    takes.erase(takes.begin());  // shape
    for (const std::string& key : any_shape) {
        if (any.has(key) && !spec.find(key)) {
            throw SceneError(any.child_path(key),
                             with_article(shape) + " surface has no " + key +
                                 (takes.empty() ? "" : " (it takes " + joined(takes) + ")"));
        }
    }
    // Only the shape's own keys are left: read them as declared.
    SpecReader r(j, path, spec);
    return entry->read(r, semi_diameter);
}

}  // namespace lenslab
