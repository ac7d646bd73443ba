#include "property_panel.h"

#include <QApplication>
#include <QFormLayout>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "geometry/implicit_solid.h"
#include "geometry/lens/sag_formula_surface.h"
#include "image/image_io.h"
#include "json_pointer.h"
#include "number_field.h"
#include "optics/glass_library.h"
#include "optics/spectrum.h"
#include "optics/user_glass_catalogues.h"
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
#include "scene/surface_json.h"
#include "scene_document.h"

// The panel itself: which form the selection asks for, and every edit committed through the
// document. The rows come from the field factory (property_fields.cpp), the forms from
// property_material_forms.cpp and property_object_forms.cpp; the scene-wide ones are here.

namespace lenslab::gui {

using nlohmann::json;

PropertyPanel::PropertyPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_error(new QLabel(this)) {
    auto* layout = new QVBoxLayout(this);
    m_error->setObjectName("property_error");
    m_error->setWordWrap(true);
    m_error->setStyleSheet("color: #c0392b;");
    layout->addStretch(1);
    layout->addWidget(m_error);
    // A refusal is about the document as it was: any change that went in makes it stale.
    connect(document, &SceneDocument::changed, this, [this] {
        m_error->clear();
        rebuild();
    });
}

void PropertyPanel::show_pointer(const QString& pointer) {
    m_pointer = pointer;
    m_error->clear();
    rebuild();
}

const json* PropertyPanel::value_at(const std::string& key) const {
    const json& doc = m_document->json();
    const json::json_pointer p(append_pointer(m_pointer.toStdString(), key));
    return doc.contains(p) ? &doc.at(p) : nullptr;
}

void PropertyPanel::commit(const std::string& key, const json& value, const QString& label) {
    // A field of a flag written as `true` ("detector": true) turns the flag into an object.
    if (const size_t slash = key.rfind('/'); slash != std::string::npos) {
        const json* parent = value_at(key.substr(0, slash));
        if (parent && parent->is_boolean()) {
            commit(key.substr(0, slash),
                   json{{unescape_pointer_token(key.substr(slash + 1)), value}}, label);
            return;
        }
    }
    const json* current = value_at(key);
    if (current && *current == value) return;
    QString error;
    const json::json_pointer p(append_pointer(m_pointer.toStdString(), key));
    if (m_document->set_value(p, value, tr("Change %1").arg(label), &error)) {
        m_error->clear();
    } else {
        m_error->setText(error);
        emit edit_refused(error);
        rebuild();  // show the value the document still holds
    }
}

void PropertyPanel::rebuild() {
    // The field being typed in (or the one a Tab that committed has just moved to) gets focus
    // back in the new form, so a commit never swallows what is typed next.
    QString focused;
    if (QWidget* f = QApplication::focusWidget();
        f && m_form_widget && m_form_widget->isAncestorOf(f))
        focused = f->objectName();
    build_form();
    if (focused.isEmpty()) return;
    // Shown now (a layout would show it later) so that it can take focus.
    if (isVisible()) m_form_widget->show();
    if (auto* again = m_form_widget->findChild<QWidget*>(focused))
        again->setFocus(Qt::TabFocusReason);
}

void PropertyPanel::build_form() {
    if (m_form_widget) {
        // Detached at once (so nothing finds its fields), deleted later: the edit that led
        // here may still be running inside one of them.
        m_form_widget->hide();
        m_form_widget->setParent(nullptr);
        m_form_widget->deleteLater();
    }
    m_form_widget = new QWidget(this);
    m_form = new QFormLayout(m_form_widget);
    // A row too wide for the panel (a long label beside three numbers) puts its field under
    // the label instead of running past the panel's edge.
    m_form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    static_cast<QVBoxLayout*>(layout())->insertWidget(0, m_form_widget);
    const json& doc = m_document->json();
    if (m_pointer.isEmpty() || !doc.contains(json::json_pointer(m_pointer.toStdString()))) return;
    if (m_pointer == "/description")
        build_description();
    else if (m_pointer == "/camera")
        build_camera();
    else if (m_pointer == "/render")
        build_render();
    else if (m_pointer == "/atmosphere")
        build_atmosphere();
    else if (m_pointer.startsWith("/materials/"))
        build_material_entry();
    else if (m_pointer.startsWith("/objects/"))
        build_object();
    else if (m_pointer.startsWith("/lights/"))
        build_light();
}

void PropertyPanel::build_camera() {
    add_heading(tr("Camera"));
    // The camera takes look_at or direction; the form edits the one the file gives.
    build_declared(camera_spec(), {value_at("look_at") ? "direction" : "look_at"});
}

void PropertyPanel::build_description() {
    add_heading(tr("About this scene"));
    // The file's own words: what it shows, the numbers it reproduces, what to try.
    auto* text = new QLabel(m_form_widget);
    text->setObjectName("scene_description");
    text->setWordWrap(true);
    text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    text->setText(QString::fromStdString(m_document->json()["description"].get<std::string>()));
    m_form->addRow(text);
}

void PropertyPanel::build_render() {
    add_heading(tr("Render settings"));
    build_declared(render_settings_spec());
}

void PropertyPanel::build_atmosphere() {
    add_heading(tr("Atmosphere"));
    build_medium_fields("");
    auto* remove = new QPushButton(tr("Remove atmosphere"), m_form_widget);
    remove->setObjectName("atmosphere:remove");
    remove->setToolTip(tr("Clear air again (Edit ▸ Delete does the same)"));
    connect(remove, &QPushButton::clicked, this, &PropertyPanel::delete_requested);
    m_form->addRow(QString(), remove);
}

void PropertyPanel::build_medium_fields(const std::string& prefix) {
    build_declared(medium_spec(), {}, prefix);
}

void PropertyPanel::build_light() {
    const json& l = *value_at("");
    const std::string type = l.value("type", "");
    const ElementSpec* spec = find_light_spec(type);
    add_heading(QString::fromStdString(spec ? spec->name : type));
    if (!spec) return;  // the scene reader names the unknown type
    // The colour is one of the spectrum's forms, edited with it; a laser has its wavelength.
    build_declared(*spec, {"color"});
    if (type != "laser") build_spectrum("");
}

void PropertyPanel::build_grin(const std::string& prefix) {
    // "uniform", or a gradient-index profile; picking one starts from a block that reads, and
    // the profile's own fields follow (material_spec.h says which).
    const json* profile = value_at(prefix + "grin/profile");
    const std::string kind =
        profile && profile->is_string() ? profile->get<std::string>() : "uniform";
    QStringList kinds{"uniform"};
    for (const std::string& k : grin_spec().param("profile").choices)
        kinds << QString::fromStdString(k);
    const std::string material_key = prefix.empty() ? "" : prefix.substr(0, prefix.size() - 1);
    add_choice(tr("Index profile"), prefix + "grin/profile", kind, kinds,
               [this, material_key](const std::string& chosen) {
                   json material = *value_at(material_key);
                   material.erase("grin");
                   if (chosen != "uniform") material["grin"] = grin_starting_block(chosen);
                   commit(material_key, material, tr("index profile"));
               });
    if (kind == "uniform") return;
    for (const std::string& key : grin_keys_of(kind))
        add_param(grin_spec().param(key), prefix + "grin/");
    if (value_at(prefix + "grin/center")) {
        add_vec3(tr("Profile centre"), prefix + "grin/center", json::array({0, 0, 0}), -1e6, 1e6,
                 grin_spec().param("center").doc);
    }
}

void PropertyPanel::build_spectrum(const std::string& prefix) {
    // A colour (D65-based), a named spectrum (optics/spectrum.h's table), a blackbody or a
    // line; switching rewrites the light's keys.
    const json* spectrum = value_at(prefix + "spectrum");
    std::string kind = "colour";
    if (spectrum && spectrum->is_string()) kind = spectrum->get<std::string>();
    if (spectrum && spectrum->is_object())
        kind = spectrum->contains("blackbody") ? "blackbody" : "line";
    QStringList kinds{"colour"};
    for (const NamedSpectrum& named : named_spectra()) kinds << QString::fromStdString(named.name);
    kinds << "blackbody"
          << "line";
    const std::string owner = prefix.empty() ? "" : prefix.substr(0, prefix.size() - 1);
    add_choice(tr("Spectrum"), prefix + "spectrum", kind, kinds,
               [this, owner](const std::string& chosen) {
                   json element = *value_at(owner);
                   element.erase("color");
                   element.erase("spectrum");
                   for (const NamedSpectrum& named : named_spectra()) {
                       if (chosen == named.name) element["spectrum"] = named.name;
                   }
                   if (chosen == "blackbody") element["spectrum"] = {{"blackbody", 3000}};
                   if (chosen == "line") element["spectrum"] = {{"line", 532}};
                   commit(owner, element, tr("spectrum"));
               });
    if (kind == "colour")
        add_vec3(tr("Colour"), prefix + "color", json::array({1, 1, 1}), 0, 1e6, "", true);
    if (kind == "blackbody")
        add_number(tr("Temperature (K)"), prefix + "spectrum/blackbody", 3000, kBlackbodyMinK,
                   kBlackbodyMaxK);
    if (kind == "line")
        add_number(tr("Wavelength (nm)"),
                   number_param(prefix + "spectrum/line", 532)
                       .at_least(360)
                       .at_most(830)
                       .in_unit("nm")
                       .describe("the line's wavelength"),
                   prefix + "spectrum/line");
}

}  // namespace lenslab::gui
