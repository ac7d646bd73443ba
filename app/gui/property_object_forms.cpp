// The property panel's object forms: each object type, a lens group and its elements, a lens
// surface and the shapes it may take, detectors, media, implicit solids.

#include <QFormLayout>
#include <algorithm>
#include <cmath>

#include "geometry/implicit_solid.h"
#include "image/image_io.h"
#include "json_pointer.h"
#include "number_field.h"
#include "optics/glass_library.h"
#include "optics/spectrum.h"
#include "optics/user_glass_catalogues.h"
#include "property_panel.h"
#include "scene/camera_spec.h"
#include "scene/json_reader.h"
#include "scene/lens_group_json.h"
#include "scene/light_spec.h"
#include "scene/material.h"
#include "scene/material_edits.h"
#include "scene/material_spec.h"
#include "scene/medium.h"
#include "scene/mirror_json.h"
#include "scene/object_spec.h"
#include "scene/object_types.h"
#include "scene/planar_json.h"
#include "scene/render_settings_spec.h"
#include "scene/surface_shapes.h"
#include "scene_document.h"

namespace lenslab::gui {

using nlohmann::json;

void PropertyPanel::build_object() {
    const json& o = *value_at("");
    const std::string type = o.value("type", "");
    add_heading(QString::fromStdString(type));
    add_text(tr("Name"), "name", "");
    if (type == "sphere") {
        add_param(sphere_spec().param("center"));
        add_param(sphere_spec().param("radius"));
    } else if (type == "triangle") {
        for (int i = 0; i < 3; ++i) {
            add_vec3(tr("Vertex %1").arg(i + 1), "vertices/" + std::to_string(i),
                     json::array({0, 0, 0}));
        }
    } else if (type == "disc" || type == "rectangle") {
        build_flat(type);
    } else if (type == "lens") {
        build_lens();
    } else if (type == "implicit") {
        build_implicit();
    } else if (type == "mirror") {
        const ElementSpec& declared = mirror_spec();
        build_declared(declared, {"name", "photon_target", "x_axis"});
        build_surface(tr("Surface"), "surface");
        add_vec3(QString::fromStdString(declared.param("x_axis").label), "x_axis",
                 json::array({1, 0, 0}));
    } else if (type == "lens_group") {
        build_lens_group();  // each element has its own material
        return;
    } else if (const ObjectTypeEntry* kind = find_object_type(type); kind && kind->spec) {
        // A declared kind with no form of its own: its declaration's fields, in order (the
        // common ones are added around it).
        build_declared(kind->spec(), {"name", "photon_target"});
    }
    if (type == "triangle" || type == "disc" || type == "rectangle") build_detector();
    const bool solid = type == "sphere" || type == "lens" || type == "implicit" || type == "box" ||
                       type == "prism" || type == "mesh";
    if (solid) build_medium();
    add_flag(tr("Photon target (aim caustic photons)"), "photon_target", tr("auto"));
    add_heading(tr("Material"));
    build_material_ref(tr("Material"), "material");
}

// A named material is chosen from the list; an inline one is edited here.

void PropertyPanel::build_lens_group() {
    const ElementSpec& group = lens_group_spec();
    for (const char* key : {"vertex", "axis", "diameter"}) add_param(group.param(key));
    const ElementSpec& element = lens_group_element_spec();
    const json* elements = value_at("elements");
    if (!elements || !elements->is_array()) return;
    const ElementSpec& mirror = lens_group_mirror_spec();
    for (size_t i = 0; i < elements->size(); ++i) {
        const std::string e = "elements/" + std::to_string(i) + "/";
        if (value_at(e + "mirror")) {
            add_heading(tr("Element %1: mirror").arg(i + 1));
            build_surface(tr("Mirror surface"), e + "mirror");
            add_param(mirror.param("hole_diameter"), e);
            add_param(mirror.param("tilt_x"), e);
            add_param(mirror.param("tilt_y"), e);
            if (i + 1 < elements->size()) add_param(mirror.param("gap"), e);
            build_material_ref(tr("Coating"), e + "material");
            continue;
        }
        add_heading(tr("Element %1").arg(i + 1));
        build_surface(tr("Front surface"), e + "front");
        add_param(element.param("thickness"), e);
        // A cemented element's back is the next element's front.
        if (value_at(e + "back")) build_surface(tr("Back surface"), e + "back");
        if (i + 1 < elements->size()) add_param(element.param("gap"), e);
        for (const char* key : {"decenter_x", "decenter_y", "tilt_x", "tilt_y", "tilt_z"})
            add_param(element.param(key), e);
        build_material_ref(tr("Material"), e + "material");
    }
}

void PropertyPanel::build_lens() {
    // One declaration holds both forms; the form shows the keys of the one the file uses.
    const ElementSpec& declared = lens_spec();
    add_param(declared.param("center"));
    add_param(declared.param("axis"));
    if (value_at("curvature_radius")) {
        add_param(declared.param("curvature_radius"));
        add_param(declared.param("aperture_radius"));
        return;
    }
    add_param(declared.param("thickness"));
    add_param(declared.param("diameter"));
    build_surface(tr("Front surface"), "front");
    build_surface(tr("Back surface"), "back");
    // Where local +x points matters only for z(x, y) faces; left out, it is a fixed
    // perpendicular to the axis, shown as +x.
    add_vec3(QString::fromStdString(declared.param("x_axis").label), "x_axis",
             json::array({1, 0, 0}));
    // Moved from the axis it is designed on (tolerancing's decentres and tilts).
    for (const char* key : {"decenter_x", "decenter_y", "tilt_x", "tilt_y", "tilt_z"})
        add_param(declared.param(key));
}

void PropertyPanel::build_surface(const QString& label, const std::string& key) {
    const json* s = value_at(key);
    const std::string shape = s ? s->value("shape", "sphere") : "sphere";
    // Switching the shape replaces the whole surface (a flat one has no radius), keeping
    // what carries over.
    const double diameter = value_at("diameter") ? value_at("diameter")->get<double>() : 1.0;
    QStringList shapes;
    for (const SurfaceShapeEntry& e : surface_shapes()) shapes << QString::fromStdString(e.name);
    add_choice(label, key + "/shape", shape, shapes,
               [this, key, label, diameter](const std::string& chosen) {
                   const SurfaceShapeEntry* entry = find_surface_shape(chosen);
                   const json* current = value_at(key);
                   if (entry)
                       commit(key, entry->start(current ? *current : json::object(), diameter),
                              label);
               });
    // The shape's declared fields, labelled with the face they belong to, showing what a new
    // face of the shape starts with where the file has nothing.
    const SurfaceShapeEntry* entry = find_surface_shape(shape);
    if (!entry) return;
    const json fresh = entry->start(json::object(), diameter);
    for (ParamSpec p : entry->spec().params) {
        if (p.label.empty()) continue;
        p.label = label.toStdString() + " " + p.label;
        const json shown = fresh.contains(p.key) ? fresh[p.key] : p.fallback;
        if (p.kind == ParamKind::String && entry->check_formula) {
            add_formula(QString::fromStdString(p.label), key + "/" + p.key,
                        shown.is_string() ? shown.get<std::string>() : "", entry->check_formula);
            continue;
        }
        if (p.fallback.is_null()) p.fallback = shown;
        add_param(p, key + "/");
    }
}

void PropertyPanel::build_flat(const std::string& type) {
    const ElementSpec& declared = type == "disc" ? disc_spec() : rectangle_spec();
    add_param(declared.param("center"));
    add_param(declared.param("normal"));
    if (type == "disc") {
        add_param(declared.param("radius"));
    } else {
        add_number(tr("Width (along u)"), "size/0", 1.0, 1e-9, 1e6);
        add_number(tr("Height (along v)"), "size/1", 1.0, 1e-9, 1e6);
    }
    // Left out, up is [0, 1, 0] (or [0, 0, -1] for a vertical normal); shown as given.
    add_vec3(QString::fromStdString(declared.param("up").label), "up", json::array({0, 1, 0}));
}

void PropertyPanel::build_detector() {
    add_heading(tr("Detector"));
    const json* d = value_at("detector");
    const bool on = d && !(d->is_boolean() && !d->get<bool>());
    add_choice(tr("Measures irradiance"), "detector", on ? "yes" : "no", {"no", "yes"},
               [this](const std::string& chosen) {
                   json element = *value_at("");
                   if (chosen == "yes")
                       element["detector"] = {
                           {"resolution", detector_spec().param("resolution").fallback}};
                   else
                       element.erase("detector");
                   commit("", element, tr("detector"));
               });
    if (!on) return;
    // A number or two per side, each in the declared range.
    const ElementSpec& declared = detector_spec();
    const ParamSpec& cells = declared.param("resolution");
    const long long fallback = cells.fallback.get<long long>();
    const auto low = static_cast<long long>(cells.min->value);
    const auto high = static_cast<long long>(cells.max->value);
    const json* resolution = value_at("detector/resolution");
    if (resolution && resolution->is_array()) {
        add_integer(tr("Cells along u"), "detector/resolution/0", fallback, low, high);
        add_integer(tr("Cells along v"), "detector/resolution/1", fallback, low, high);
    } else {
        add_integer(tr("Cells (longer side)"), "detector/resolution", fallback, low, high);
    }
    add_param(declared.param("side"), "detector/");
    // A number of bands shows as the edges it stands for (equal bands over 360-830 nm).
    json edges = declared.param("bands").fallback;
    if (const json* bands = value_at("detector/bands");
        bands && bands->is_number_integer() && bands->get<int>() > 0) {
        edges = json::array();
        const int n = bands->get<int>();
        for (int i = 0; i <= n; ++i)
            edges.push_back(kLambdaMinNm + (kLambdaMaxNm - kLambdaMinNm) * i / n);
    }
    add_number_list(tr("Band edges (nm)"), "detector/bands", edges, 17);
    add_param(declared.param("unit"), "detector/");
}

void PropertyPanel::build_medium() {
    add_heading(tr("Medium"));
    const bool on = value_at("medium") != nullptr;
    add_choice(tr("Fills it"), "medium", on ? "yes" : "no", {"no", "yes"},
               [this](const std::string& chosen) {
                   json element = *value_at("");
                   if (chosen == "yes") {
                       element["medium"] = medium_spec().example;
                   } else {
                       element.erase("medium");
                       // Only a medium's edge had no material: it becomes a plain surface.
                       if (!element.contains("material")) element["material"] = {{"color", 0.7}};
                   }
                   commit("", element, tr("medium"));
               });
    if (!on) return;
    build_medium_fields("medium/");
}

void PropertyPanel::build_implicit() {
    const ElementSpec& declared = implicit_spec();
    add_param(declared.param("center"));
    // The formula is checked as it is typed; the bounds are two corners.
    add_formula(QString::fromStdString(declared.param("formula").label), "formula",
                "x^2 + y^2 + z^2 - 1", ImplicitSolid::check);
    add_vec3(tr("Bounds, lower corner"), "bounds/0", json::array({-1, -1, -1}));
    add_vec3(tr("Bounds, upper corner"), "bounds/1", json::array({1, 1, 1}));
    add_param(declared.param("steps"));
}

}  // namespace lenslab::gui
