// The property panel's material forms: a scene material, an object's material reference, the
// glass chooser.

#include <QComboBox>
#include <QCompleter>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
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
#include "scene/surface_json.h"
#include "scene_document.h"

namespace lenslab::gui {

using nlohmann::json;

template <class Edit>
void PropertyPanel::apply_material_edit(const QString& label, const Edit& edit) {
    QString select, error;
    try {
        const json edited = edit(m_document->json(), select);
        if (m_document->apply(edited, label, &error)) {
            m_error->clear();
            emit pointer_requested(select);
            return;
        }
    } catch (const MaterialEditError& e) {
        error = QString::fromStdString(e.what());
    }
    m_error->setText(error);
    emit edit_refused(error);
    rebuild();
}

void PropertyPanel::build_material_entry() {
    const std::string name = split_pointer(m_pointer).value(1).toStdString();
    const auto to_pointer = [](const std::string& material) {
        return join_pointer("/materials", QString::fromStdString(material));
    };
    add_heading(tr("Material"));
    auto* name_edit = new QLineEdit(QString::fromStdString(name), m_form_widget);
    name_edit->setObjectName("field:material_name");
    name_edit->setToolTip(tr("The material's name; renaming it renames every use"));
    connect(name_edit, &QLineEdit::editingFinished, this, [this, name_edit, name, to_pointer] {
        const std::string to = name_edit->text().trimmed().toStdString();
        if (to == name) return;
        apply_material_edit(tr("Rename material"), [&](const json& doc, QString& select) {
            select = to_pointer(to);
            return rename_material(doc, name, to);
        });
    });
    m_form->addRow(tr("Name"), name_edit);
    auto* buttons = new QWidget(m_form_widget);
    auto* row = new QHBoxLayout(buttons);
    row->setContentsMargins(0, 0, 0, 0);
    const auto add_button = [&](const QString& text, const char* object_name, auto edit) {
        auto* b = new QPushButton(text, buttons);
        b->setObjectName(object_name);
        connect(b, &QPushButton::clicked, this,
                [this, text, edit] { apply_material_edit(text, edit); });
        row->addWidget(b);
    };
    add_button(tr("New"), "material:new", [to_pointer](const json& doc, QString& select) {
        std::string added;
        json out = add_material(doc, "material", &added);
        select = to_pointer(added);
        return out;
    });
    add_button(tr("Duplicate"), "material:duplicate",
               [name, to_pointer](const json& doc, QString& select) {
                   std::string added;
                   json out = duplicate_material(doc, name, &added);
                   select = to_pointer(added);
                   return out;
               });
    add_button(tr("Delete"), "material:delete", [name](const json& doc, QString& select) {
        select = QString();
        return delete_material(doc, name);
    });
    m_form->addRow(buttons);
    build_material("");
}

void PropertyPanel::build_material(const std::string& prefix) {
    const ElementSpec& declared = material_spec();
    for (const char* key : {"color", "transparency", "specular"})
        add_param(declared.param(key), prefix);
    const json* glass = value_at(prefix + "glass");
    const std::string material_key = prefix.empty() ? "" : prefix.substr(0, prefix.size() - 1);
    add_glass_choice(prefix + "glass", material_key,
                     glass && glass->is_string() ? glass->get<std::string>() : "");
    // A melt's departure from the catalogue (a melt sheet's, or a tolerance's).
    if (glass) {
        for (const char* key : {"delta_n_d", "delta_V_d"}) add_param(declared.param(key), prefix);
    }
    const json* ior = value_at(prefix + "ior");
    // A gradient index replaces the constant one (a glass still gives it its dispersion).
    const bool constant = !glass && !value_at(prefix + "grin");
    if (constant && (!ior || ior->is_number())) {
        add_param(declared.param("ior"), prefix);
    } else if (constant) {
        m_form->addRow(tr("Refractive index"),
                       new QLabel(tr("dispersion model (edit the file)"), m_form_widget));
    }
    build_grin(prefix);
    // Shown as 0 while there is no emission (the intensity an emission block defaults to is 1).
    const json* emission = value_at(prefix + "emission");
    ParamSpec intensity = emission_spec().param("intensity");
    if (!emission) intensity.fallback = 0.0;
    add_param(intensity, prefix + "emission/");
    if (emission) {
        build_spectrum(prefix + "emission/");
    } else {
        add_param(emission_spec().param("color"), prefix + "emission/");
    }
}

namespace {

// "constant index", the built-in materials, then every maker's glass as a scene names it: its
// plain name where that finds it, else MAKER:NAME. Computed once (1,635 lookups).
const QStringList& glass_choices() {
    static const QStringList names = [] {
        QStringList out{QObject::tr("constant index")};
        for (const Glass& g : glass_catalogue()) out << QString::fromStdString(g.name);
        try {
            for (const Glass& g : maker_glasses()) {
                const bool plain = lookup_glass(g.name).glass == &g;
                out << QString::fromStdString(plain ? g.name : g.maker + ":" + g.name);
            }
        } catch (const std::exception&) {
            // No catalogue files: the built-in materials only (lookups will say why).
        }
        return out;
    }();
    return names;
}

}  // namespace

void PropertyPanel::add_glass_choice(const std::string& key, const std::string& material_key,
                                     const std::string& current) {
    auto* box = new QComboBox(m_form_widget);
    box->setObjectName(QString::fromStdString("field:" + key));
    box->setEditable(true);
    box->setInsertPolicy(QComboBox::NoInsert);
    box->setMaxVisibleItems(20);
    box->addItems(glass_choices());
    // The scene's own catalogues ("glass_catalogues"), after the built-in materials, as
    // lookups take them; loaded when the scene was read, so listed afresh each time.
    int at = 1 + int(glass_catalogue().size());
    for (const Glass* g : user_glasses())
        box->insertItem(at++, QString::fromStdString(g->maker + ":" + g->name));
    // Typing finds a glass anywhere in its name ("bk7" offers N-BK7, S-BSL7 needs "bsl").
    box->completer()->setFilterMode(Qt::MatchContains);
    box->completer()->setCaseSensitivity(Qt::CaseInsensitive);
    box->completer()->setCompletionMode(QCompleter::PopupCompletion);
    box->setToolTip(
        tr("A built-in material, a glass of the scene's own catalogues (CATALOGUE:NAME), or "
           "a glass of the SCHOTT, OHARA, CDGM, HOYA, HIKARI and SUMITA catalogues "
           "(MAKER:NAME where makers share a name); type to search. \"constant index\" "
           "types an index instead."));
    box->setCurrentText(QString::fromStdString(current.empty() ? "constant index" : current));
    const auto choose = [this, box, material_key, current] {
        const std::string chosen = box->currentText().trimmed().toStdString();
        if (chosen == current || (current.empty() && chosen == "constant index")) return;
        json material = *value_at(material_key);
        material.erase("glass");
        material.erase("ior");
        if (chosen == "constant index") {
            material["ior"] = 1.5;
        } else if (const GlassLookup found = lookup_glass(chosen); !found.glass) {
            const QString reason = tr("Glass: %1").arg(QString::fromStdString(found.error));
            m_error->setText(reason);
            emit edit_refused(reason);
            return;
        } else {
            material["glass"] = chosen;
        }
        commit(material_key, material, tr("glass"));
    };
    connect(box, &QComboBox::activated, this, choose);
    connect(box->lineEdit(), &QLineEdit::editingFinished, this, choose);
    m_form->addRow(tr("Glass"), box);
}

void PropertyPanel::build_material_ref(const QString& label, const std::string& key) {
    QStringList names;
    if (m_document->json().contains("materials")) {
        for (const auto& [name, v] : m_document->json()["materials"].items())
            names << QString::fromStdString(name);
    }
    const json* m = value_at(key);
    if (m && m->is_string()) {
        add_choice(label, key, m->get<std::string>(), names);
        // Materials are shared by name: editing one changes every object that names it.
        const std::string reference = append_pointer(m_pointer.toStdString(), key);
        const size_t users = material_users(m_document->json(), m->get<std::string>()).size();
        auto* unique = new QPushButton(tr("Make unique"), m_form_widget);
        unique->setObjectName(QString::fromStdString("material:make_unique:" + key));
        unique->setToolTip(users > 1 ? tr("Give this object a copy of the material, so editing "
                                          "it changes nothing else (%1 uses share it now)")
                                           .arg(users)
                                     : tr("Only this object uses the material"));
        unique->setEnabled(users > 1);
        connect(unique, &QPushButton::clicked, this, [this, reference] {
            apply_material_edit(tr("Make material unique"), [&](const json& doc, QString& select) {
                std::string added;
                json out = make_material_unique(doc, reference, &added);
                select = join_pointer("/materials", QString::fromStdString(added));
                return out;
            });
        });
        m_form->addRow(QString(), unique);
    } else {
        build_material(key + "/");
    }
}

}  // namespace lenslab::gui
