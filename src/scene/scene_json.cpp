#include "scene/scene_json.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "math/formula.h"
#include "optics/grin_profile.h"
#include "optics/melt_index.h"
#include "scene/atmosphere_region.h"
#include "scene/camera_spec.h"
#include "scene/glass_catalogues_json.h"
#include "scene/json_reader.h"
#include "scene/lens_file_json.h"
#include "scene/lens_group_json.h"
#include "scene/light_spec.h"
#include "scene/limits.h"
#include "scene/material_spec.h"
#include "scene/medium_convention.h"
#include "scene/mesh_json.h"
#include "scene/object_types.h"
#include "scene/planar_json.h"
#include "scene/render_settings_json.h"
#include "scene/render_settings_spec.h"
#include "scene/spec_reader.h"
#include "scene/spectral_json.h"
#include "scene/surface_json.h"

namespace lenslab {

namespace {

using nlohmann::json;

void read_camera(const json& j, CameraSettings& cam) {
    SpecReader r(j, "camera", camera_spec());
    cam.position = r.point("position");
    if (!r.has("look_at") && !r.has("direction")) {
        throw SceneError("camera", "give look_at (a point) or direction (a vector)");
    }
    if (r.has("look_at") && r.has("direction")) {
        throw SceneError("camera.direction", "give either look_at or direction, not both");
    }
    if (r.has("look_at")) {
        const Vec3 d = r.point("look_at") - cam.position;
        if (!(length(d) > 1e-12)) throw SceneError("camera.look_at", "must differ from position");
        cam.direction = normalize(d);
    } else {
        cam.direction = r.unit_vector("direction");
    }
    const bool up_given = r.has("up");
    cam.up = r.unit_vector("up");
    if (length(cross(cam.up, cam.direction)) < 1e-9) {
        throw SceneError("camera.up", up_given ? "must not be parallel to the view direction"
                                               : "the default up [0, 1, 0] is parallel to the view "
                                                 "direction; give camera.up");
    }
    cam.fov_deg = r.real("fov");
}

// Keys, defaults and ranges come from render_settings_spec(); what stays here are the
// rules between fields.
void read_render(const json& j, RenderSettings& s) {
    SpecReader r(j, "render", render_settings_spec());
    s.width = static_cast<int>(r.whole("width"));
    s.height = static_cast<int>(r.whole("height"));
    if (auto problem = image_size_problem(s.width, s.height)) throw SceneError("render", *problem);
    s.spp = static_cast<int>(r.whole("spp"));
    s.max_depth = static_cast<int>(r.whole("max_depth"));
    s.seed = static_cast<uint64_t>(r.whole("seed"));
    s.ambient = r.colour("ambient");
    s.background = r.colour("background");
    s.light_samples = static_cast<int>(r.whole("light_samples"));
    s.min_weight = r.real("min_weight");
    s.grin_tolerance = r.real("grin_tolerance");
    s.integrator = r.text("integrator");
    s.dispersion_samples = static_cast<int>(r.whole("dispersion_samples"));
    s.merge_weight = r.real("merge_weight");
    s.photons = r.whole("photons");
    s.radius = r.real("radius");
    s.filter = choice_named<PhotonFilter>(kPhotonFilterNames, r.text("filter"));
    s.filter_k = r.real("filter_k");
    s.max_photons_per_estimate = static_cast<int>(r.whole("max_photons_per_estimate"));
    s.direct = choice_named<DirectLight>(kDirectLightNames, r.text("direct"));
    s.passes = static_cast<int>(r.whole("passes"));
    s.time = r.real("time");
    if (s.passes == 0 && s.time == 0.0) {
        throw SceneError("render.passes",
                         "0 means no pass limit, which needs a time budget: give render.time > 0");
    }
    s.pass_photons = r.whole("pass_photons");
    s.caustic_photons = r.whole("caustic_photons");
    s.aim_photons = r.flag("aim_photons");
    s.initial_radius = r.real("initial_radius");
    s.alpha = r.real("alpha");
    s.volume_neighbours = static_cast<int>(r.whole("volume_neighbours"));
    s.tone_map = choice_named<ToneMapCurve>(kToneMapNames, r.text("tone_map"));
    s.highlight_stops = r.real("highlight_stops");
}

std::shared_ptr<const GrinProfile> read_grin(const json& j, const std::string& path) {
    SpecReader r(j, path, grin_spec());
    auto g = std::make_shared<GrinProfile>();
    g->owner = path;
    const std::string profile = r.text("profile");
    for (GrinKind k : {GrinKind::Luneburg, GrinKind::Fisheye, GrinKind::Radial, GrinKind::Axial,
                       GrinKind::Formula}) {
        if (profile == grin_kind_name(k)) g->kind = k;
    }
    g->n0 = r.real("n0");
    g->A = r.real("A");
    g->axis = r.unit_vector("axis");
    if (r.has("center")) {
        g->has_centre = true;
        g->centre = r.point("center");
    }
    const bool spherical = g->kind == GrinKind::Luneburg || g->kind == GrinKind::Fisheye;
    if (spherical) {
        if (!r.has("radius"))
            throw SceneError(r.child_path("radius"), "missing (required by the " + profile +
                                                         " profile: its sphere's radius R)");
        g->radius = r.real("radius");
    }
    if (g->kind == GrinKind::Formula) {
        const json* f = r.find("formula");
        if (!f || !f->is_string())
            throw SceneError(r.child_path("formula"),
                             "missing or not a string (required by the formula profile)");
        try {
            g->formula = std::make_shared<Formula>(
                f->get<std::string>(), std::vector<std::string>{"x", "y", "z"}, kGrinFormulaHint);
        } catch (const FormulaError& e) {
            throw SceneError(r.child_path("formula"), e.message());
        }
    }
    return g;
}

Material read_material(const json& j, const std::string& path, const std::string& name) {
    SpecReader r(j, path, material_spec());
    Material m;
    m.name = name;
    m.color = r.colour("color");
    m.transparency = r.real("transparency");
    m.specular = r.real("specular");
    if (m.transparency + m.specular > 1.0 + 1e-12) {
        throw SceneError(r.child_path("specular"),
                         "transparency + specular must be at most 1, got " +
                             format_number(m.transparency + m.specular));
    }
    if (r.has("ior") && r.has("glass")) {
        throw SceneError(r.child_path("glass"), "give either ior or glass, not both");
    }
    for (const char* key : {"delta_n_d", "delta_V_d"}) {
        if (r.real(key) != 0 && !r.has("glass"))
            throw SceneError(r.child_path(key), "a melt's departure needs a catalogue `glass`");
    }
    if (const json* g = r.find("glass")) {
        const Glass& glass = read_glass(*g, r.child_path("glass"));
        const double dn = r.real("delta_n_d"), dv = r.real("delta_V_d");
        if (!(glass.model->n_d() + dn > 1.0))
            throw SceneError(r.child_path("delta_n_d"), "leaves the melt's n_d at or below 1");
        if (!(glass.model->abbe_number() + dv > 0.0))
            throw SceneError(r.child_path("delta_V_d"), "leaves the melt's V_d at or below 0");
        m.index = melt_index(glass.model, dn, dv);
        // A maker's glass is named with its maker (the bench's reports, the ray diagram), a
        // name lookups take back and that stays unambiguous (SCHOTT:SF10, HIKARI:SF10).
        m.glass = glass.maker.empty() ? glass.name : glass.maker + ":" + glass.name;
    } else if (const json* n = r.find("ior")) {
        m.index = n->is_number() ? constant_index(r.real("ior"))
                                 : read_index_model(*n, r.child_path("ior"));
    }
    if (const json* g = r.find("grin")) {
        if (!(m.transparency > 0.0))
            throw SceneError(r.child_path("grin"),
                             "a GRIN index needs a transparent material (transparency > 0)");
        m.grin = read_grin(*g, r.child_path("grin"));
    }
    if (const json* e = r.find("emission")) {
        SpecReader er(*e, r.child_path("emission"), emission_spec());
        if (const json* s = er.find("spectrum")) {
            if (er.has("color"))
                throw SceneError(er.child_path("color"), "give either color or spectrum, not both");
            m.emission_spectrum = read_spectrum(*s, er.child_path("spectrum"));
        }
        m.emission_color = er.colour("color");
        m.emission_intensity = er.real("intensity");
    }
    m.finish();
    return m;
}

std::map<std::string, int> read_materials(const json& j, std::vector<Material>& out) {
    std::map<std::string, int> by_name;
    if (!j.is_object())
        throw SceneError("materials", "must be an object mapping names to materials");
    for (const auto& [name, value] : j.items()) {
        by_name[name] = static_cast<int>(out.size());
        out.push_back(read_material(value, "materials." + name, name));
    }
    return by_name;
}

int read_material_ref(JsonObjectReader& r, const std::string& owner_name,
                      const std::map<std::string, int>& materials, std::vector<Material>& all) {
    const json& m = r.require("material");
    const std::string path = r.child_path("material");
    if (m.is_object()) {
        all.push_back(read_material(m, path, owner_name));
        return static_cast<int>(all.size()) - 1;
    }
    if (!m.is_string())
        throw SceneError(path, "must be a material name or a material object { ... }");
    const std::string name = m.get<std::string>();
    const auto it = materials.find(name);
    if (it != materials.end()) return it->second;
    std::vector<std::string> names;
    for (const auto& [known, index] : materials) names.push_back(known);
    const std::string best = closest_match(name, names);
    throw SceneError(path, "unknown material '" + name + "' (not in materials" +
                               (best.empty() ? "" : "; did you mean '" + best + "'?") + ")");
}

// The material of a medium's boundary that is only that (scene/material.h's `surfaceless`).
int add_surfaceless_material(std::vector<Material>& all) {
    Material m;
    m.name = "surfaceless";
    m.color = Rgb{0, 0, 0};
    m.surfaceless = true;
    m.finish();
    all.push_back(std::move(m));
    return static_cast<int>(all.size()) - 1;
}

void check_not_emitting(JsonObjectReader& r, const Material& m) {
    if (m.is_emitter()) {
        throw SceneError(r.child_path("material"),
                         "only spheres can emit light (the material has an emission)");
    }
}

SceneObject read_object(const json& j, const std::string& path,
                        const std::map<std::string, int>& materials, std::vector<Material>& all,
                        const std::string& base_dir) {
    const std::string type = read_type_key(j, path);
    const ObjectTypeEntry* kind = find_object_type(type);
    if (!kind || !kind->read) throw SceneError(path + ".type", unknown_object_type_message(type));
    SceneObject o;
    o.type = kind->type;
    if (!kind->detector_size_key) check_detector_allowed(j, path, type);
    // Every kind reads through its declaration.
    SpecReader r(j, path, kind->spec());
    o.name = r.string("name", path);
    o.photon_target = r.boolean("photon_target");
    o.shape = kind->read(r, base_dir);
    if (kind->detector_size_key) o.detector = read_detector(r);
    if (o.detector) check_detector_size(*o.shape, *o.detector, path, kind->detector_size_key);
    if (const json* m = r.find("medium")) {
        if (!o.shape->is_closed()) {
            throw SceneError(r.child_path("medium"),
                             "a medium fills a solid: this " + type + " is an open surface");
        }
        o.medium = read_medium(*m, r.child_path("medium"), o.shape->bounds());
    }
    o.material = o.medium && !r.has("material") ? add_surfaceless_material(all)
                                                : read_material_ref(r, o.name, materials, all);
    if (kind->open_mesh_check) check_mesh_material(r, *o.shape, all[o.material]);
    if (!kind->may_emit) check_not_emitting(r, all[o.material]);
    if (all[o.material].grin && !o.shape->is_closed()) {
        throw SceneError(r.child_path("material"),
                         "a GRIN material fills a solid: this object is an open surface");
    }
    if (const GrinProfile* g = all[o.material].grin.get()) {
        const Aabb box = o.shape->bounds();
        if (auto why = g->problem_in(g->has_centre ? g->centre : box.centre(), box.lo, box.hi))
            throw SceneError(r.child_path("material"), "its GRIN index: " + *why);
    }
    return o;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& source, const std::string& base_dir,
                  const SceneReadOptions& options) {
    const json root = parse_json_strict(text, source);
    if (!root.is_object()) throw SceneError(source, "the top level must be a JSON object { ... }");
    return scene_from_json(root, base_dir, options);
}

Scene scene_from_json(const nlohmann::json& root, const std::string& base_dir,
                      const SceneReadOptions& options) {
    JsonObjectReader r(
        root, "",
        {"version", "description", "camera", "render", "materials", "objects", "lights",
         "atmosphere", "ambient", "length_unit_mm", "glass_catalogues", "bench"});
    const int version = r.integer("version", 1, 1, 1000);
    if (version != 1) throw SceneError("version", "this lenslab reads version 1 scene files");
    (void)r.string("description", "");
    const SceneMediumConvention convention{
        r.choice("ambient", "air", {"air", "vacuum"}) == "vacuum",
        r.positive("length_unit_mm", 1.0)};
    // The system data of an imported lens file (wavelengths, fields, aperture): the optical
    // bench's defaults, and `lenslab export` writes them back.
    const json* bench = r.find("bench");
    if (bench && !bench->is_object()) {
        throw SceneError("bench", "must be an object (the system data of an imported lens file)");
    }

    // Before the materials: they may name the catalogues' glasses.
    if (const json* jc = r.find("glass_catalogues")) read_glass_catalogues(*jc, base_dir);
    Scene scene;
    if (bench) scene.bench = read_lens_bench(*bench);
    if (options.require_camera || r.has("camera")) read_camera(r.require("camera"), scene.camera);
    if (const json* jr = r.find("render")) read_render(*jr, scene.render);
    std::map<std::string, int> by_name;
    if (const json* jm = r.find("materials")) by_name = read_materials(*jm, scene.materials);
    const json* atmosphere = r.find("atmosphere");
    // A homogeneous atmosphere is read first, as always; one with a density once the
    // objects and lights that bound it are known.
    if (atmosphere && !atmosphere_needs_region(*atmosphere))
        scene.atmosphere = read_atmosphere(*atmosphere, Aabb{});
    if (const json* jo = r.find("objects")) {
        if (!jo->is_array()) throw SceneError("objects", "must be an array");
        check_count(jo->size(), kMaxObjects, "objects", "objects");
        for (size_t i = 0; i < jo->size(); ++i) {
            const std::string path = element_path("objects", i);
            const std::string type = read_type_key((*jo)[i], path);
            if (type == "lens_group" || type == "lens_file") {
                json file_bench;
                const json group = type == "lens_file" ? lens_group_from_lens_file(
                                                             (*jo)[i], path, base_dir, &file_bench)
                                                       : (*jo)[i];
                // The first lens file's system data, unless the scene has its own.
                if (!scene.bench && file_bench.is_object() && !file_bench.empty()) {
                    scene.bench = read_lens_bench(file_bench);
                    scene.bench->object = static_cast<int>(i);
                }
                const auto material = [&](JsonObjectReader& element, const std::string& owner) {
                    const int m = read_material_ref(element, owner, by_name, scene.materials);
                    check_not_emitting(element, scene.materials[m]);
                    return m;
                };
                for (SceneObject& o : read_lens_group(group, path, material)) {
                    o.source = static_cast<int>(i);
                    scene.objects.push_back(std::move(o));
                }
                continue;
            }
            scene.objects.push_back(
                read_object((*jo)[i], path, by_name, scene.materials, base_dir));
            scene.objects.back().source = static_cast<int>(i);
        }
        // A lens group adds one object per element.
        check_count(scene.objects.size(), kMaxObjects, "objects",
                    "objects (lens group elements counted one by one)");
    }
    apply_medium_convention(convention, scene.materials);
    if (const json* jl = r.find("lights")) {
        scene.set_lights(lights_from_json(*jl));  // lights() too: the atmosphere's box holds them
    }
    if (atmosphere && atmosphere_needs_region(*atmosphere))
        scene.atmosphere = read_atmosphere(*atmosphere, atmosphere_region(scene));
    if (options.build_for_rendering) scene.build();
    return scene;
}

CameraSettings camera_from_json(const nlohmann::json& camera) {
    CameraSettings settings;
    read_camera(camera, settings);
    return settings;
}

namespace {

// Prefixes the file name so a message says where, whatever the JSON path.
template <typename Fn>
auto naming_file(const std::string& path, Fn&& fn) {
    try {
        return fn();
    } catch (const SceneError& e) {
        if (e.path() == path || e.path().empty()) throw SceneError(path, e.reason());
        throw SceneError(path + ": " + e.path(), e.reason());
    }
}

}  // namespace

nlohmann::json read_scene_json_file(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw SceneError(path, "is a directory, not a scene file");
    }
    // Before opening: a device (/dev/zero) would never end, a huge file would fill memory.
    if (auto problem = file_read_problem(path, kMaxSceneFileBytes)) {
        throw SceneError(path, "cannot read scene file: it " + *problem);
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path, std::string("cannot open scene file: ") + std::strerror(errno));
    // Read into one string of the file's size: a stream buffer and its copy would hold the
    // text twice (512 MiB for the largest file allowed).
    std::string text;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec) text.reserve(static_cast<size_t>(std::min<uintmax_t>(size, kMaxSceneFileBytes)));
    std::array<char, 1 << 16> chunk;
    while (in.read(chunk.data(), chunk.size()) || in.gcount() > 0) {
        text.append(chunk.data(), static_cast<size_t>(in.gcount()));
        if (text.size() > kMaxSceneFileBytes) {
            throw SceneError(path, "cannot read scene file: it grew past the " +
                                       std::to_string(kMaxSceneFileBytes >> 20) +
                                       " MiB allowed while being read");
        }
    }
    if (in.bad()) throw SceneError(path, "cannot read scene file");
    return naming_file(path, [&] {
        json root = parse_json_strict(text, path);
        if (!root.is_object())
            throw SceneError(path, "the top level must be a JSON object { ... }");
        return root;
    });
}

Scene scene_from_file_json(const nlohmann::json& root, const std::string& path,
                           const SceneReadOptions& options) {
    // Files a scene names (OBJ meshes) are found next to it.
    return naming_file(path, [&] {
        return scene_from_json(root, std::filesystem::path(path).parent_path().string(), options);
    });
}

Scene load_scene_file(const std::string& path, const SceneReadOptions& options) {
    return scene_from_file_json(read_scene_json_file(path), path, options);
}

RenderSettings read_render_settings(const nlohmann::json& render) {
    RenderSettings s;
    read_render(render, s);
    return s;
}

Scene default_scene() { return parse_scene(default_scene_text(), "default scene"); }

}  // namespace lenslab
