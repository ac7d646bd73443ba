#include "property_panel.h"

#include <QApplication>
#include <QColorDialog>
#include <QComboBox>
#include <QCompleter>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>
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

namespace lenslab::gui {

namespace {

using nlohmann::json;

QStringList to_qt(const std::vector<std::string>& names) {
    QStringList out;
    for (const auto& n : names) out << QString::fromStdString(n);
    return out;
}

// A colour given as one number means grey; the form always edits three components.
json as_triple(const json& v) {
    if (v.is_number()) return json::array({v, v, v});
    return v;
}

// A number as a formula term: negative ones in parentheses.
std::string term(double v) {
    std::string s = format_number(v);
    if (v < 0) {  // built in place: GCC 12 warns falsely (-Wrestrict) on "(" + s + ")"
        s.insert(0, 1, '(');
        s.push_back(')');
    }
    return s;
}

// The sag formula of a conic or even asphere with these parameters, so that switching a
// surface to "sag" keeps its shape and shows how it is written.
std::string sag_formula_of(const json& s) {
    if (!s.contains("radius")) return "0";
    const double radius = s.value("radius", 1.0), k = s.value("k", 0.0);
    const std::string q = k == 0 ? "" : term(1 + k) + "*";
    std::string f =
        "r^2/(" + term(radius) + "*(1 + sqrt(1 - " + q + "r^2/" + term(radius) + "^2)))";
    if (s.contains("coefficients") && s["coefficients"].is_array()) {
        int power = 4;
        for (const json& a : s["coefficients"]) {
            if (a.is_number() && a.get<double>() != 0)
                f += " + " + term(a.get<double>()) + "*r^" + std::to_string(power);
            power += 2;
        }
    }
    return f;
}

// A surface of shape `chosen` that keeps what it can of `current` (radius, k,
// coefficients); new lenses get a radius of twice the diameter.
json surface_of_shape(const std::string& chosen, const json* current, double diameter) {
    const json old = current && current->is_object() ? *current : json::object();
    json s{{"shape", chosen}};
    const double radius = old.contains("radius") ? old["radius"].get<double>() : 2.0 * diameter;
    if (chosen == "sphere" || chosen == "conic" || chosen == "asphere") s["radius"] = radius;
    if (chosen == "conic" || chosen == "asphere") s["k"] = old.value("k", 0.0);
    if (chosen == "asphere")
        s["coefficients"] = old.contains("coefficients") ? old["coefficients"] : json::array({0.0});
    if (chosen == "sag")
        s["formula"] =
            old.contains("formula") ? old["formula"].get<std::string>() : sag_formula_of(old);
    return s;
}

QLabel* make_problem_label(QWidget* parent, const std::string& name) {
    auto* label = new QLabel(parent);
    label->setObjectName(QString::fromStdString(name));
    label->setWordWrap(true);
    label->setStyleSheet("color: #c0392b;");
    label->hide();
    return label;
}

// A text field with a (hidden) problem label under it, as one form row's widget.
struct CheckedLineEdit {
    QWidget* box;
    QLineEdit* edit;
    QLabel* problem;
};

CheckedLineEdit make_checked_line_edit(QWidget* parent, const std::string& key,
                                       const std::string& problem_name) {
    auto* box = new QWidget(parent);
    auto* v = new QVBoxLayout(box);
    v->setContentsMargins(0, 0, 0, 0);
    auto* edit = new QLineEdit(box);
    edit->setObjectName(QString::fromStdString("field:" + key));
    QLabel* problem = make_problem_label(box, problem_name);
    v->addWidget(edit);
    v->addWidget(problem);
    return {box, edit, problem};
}

}  // namespace

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
    if (m_pointer == "/camera")
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

void PropertyPanel::add_heading(const QString& text) {
    auto* heading = new QLabel("<b>" + text + "</b>", m_form_widget);
    m_form->addRow(heading);
}

NumberField* PropertyPanel::add_number_field(QWidget* parent, const ParamSpec& p,
                                             const std::string& key, const QString& label) {
    ParamSpec spec = p;
    spec.key = key;  // the field's objectName
    auto* field = new NumberField(spec, parent);
    connect(field, &NumberField::refused, this, [this, label](const QString& reason) {
        const QString message = label + ": " + reason;
        m_error->setText(message);
        emit edit_refused(message);
    });
    // Fixed without a commit (the same value typed again, or Escape): the refusal goes too,
    // when it is this field's.
    connect(field, &NumberField::problem_cleared, this, [this, label] {
        if (m_error->text().startsWith(label + ": ")) m_error->clear();
    });
    return field;
}

void PropertyPanel::add_number(const QString& label, const ParamSpec& p, const std::string& key) {
    const bool fraction = p.kind == ParamKind::Fraction;
    QWidget* row = fraction ? new QWidget(m_form_widget) : nullptr;
    NumberField* field = add_number_field(row ? row : m_form_widget.data(), p, key, label);
    const json* v = value_at(key);
    const json& d = p.fallback;
    field->setValue(v && v->is_number() ? v->get<double>() : d.is_number() ? d.get<double>() : 0.0);
    const bool whole = p.is_integer();
    connect(field, &NumberField::committed, this, [this, key, label, whole](double x) {
        if (whole) {
            commit(key, static_cast<long long>(x), label);
        } else {
            commit(key, x, label);
        }
    });
    if (!fraction) {
        m_form->addRow(label, field);
        return;
    }
    // A fraction has a slider too, in hundredths. A drag shows its value in the field and
    // commits once, when released (a commit rebuilds the form, slider included); a click or
    // a key commits at once.
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    auto* slider = new QSlider(Qt::Horizontal, row);
    slider->setObjectName(QString::fromStdString("slider:" + key));
    slider->setRange(int(std::lround(100 * field->minimum())), 100);
    slider->setValue(int(std::lround(100 * field->value())));
    slider->setToolTip(field->toolTip());
    h->addWidget(field, 1);
    h->addWidget(slider, 2);
    const auto commit_slider = [this, slider, key, label] {
        commit(key, slider->value() / 100.0, label);
    };
    connect(slider, &QSlider::valueChanged, this, [slider, field, commit_slider](int value) {
        field->setValue(value / 100.0);
        if (!slider->isSliderDown()) commit_slider();
    });
    connect(slider, &QSlider::sliderReleased, this, commit_slider);
    m_form->addRow(label, row);
}

void PropertyPanel::add_number(const QString& label, const std::string& key, double fallback,
                               double min, double max) {
    add_number(label, number_param(key, fallback).at_least(min).at_most(max), key);
}

void PropertyPanel::add_integer(const QString& label, const std::string& key, long long fallback,
                                long long min, long long max) {
    add_number(label, whole_param(key, fallback, min, max), key);
}

void PropertyPanel::add_vec3(const QString& label, const std::string& key, const json& fallback,
                             double min, double max, const std::string& doc, bool colour) {
    auto* row = new QWidget(m_form_widget);
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    const json* v = value_at(key);
    const json value = as_triple(v ? *v : fallback);
    ParamSpec component = number_param(key, 0.0).at_least(min).at_most(max).describe(doc);
    std::array<NumberField*, 3> fields{};
    for (int i = 0; i < 3; ++i) {
        fields[i] = add_number_field(row, component, key + "." + "xyz"[i], label);
        fields[i]->setValue(value.is_array() && value.size() == 3 && value[i].is_number()
                                ? value[i].get<double>()
                                : 0.0);
        h->addWidget(fields[i]);
    }
    for (int i = 0; i < 3; ++i) {
        connect(fields[i], &NumberField::committed, this, [this, fields, key, label] {
            commit(key, json::array({fields[0]->value(), fields[1]->value(), fields[2]->value()}),
                   label);
        });
    }
    if (colour) add_colour_button(row, fields, key, label, max);
    m_form->addRow(label, row);
}

void PropertyPanel::add_colour_button(QWidget* row, const std::array<NumberField*, 3>& fields,
                                      const std::string& key, const QString& label, double max) {
    // The triple is linear RGB; the picker (and the swatch) speak sRGB.
    const auto shown = [fields] {
        const auto channel = [&](int i) {
            return int(std::lround(255.0 * linear_to_srgb(fields[i]->value())));
        };
        return QColor(channel(0), channel(1), channel(2));
    };
    auto* button = new QToolButton(row);
    button->setObjectName(QString::fromStdString("colour:" + key));
    button->setToolTip(tr("Pick a colour (the numbers are linear RGB; the picker shows sRGB)"));
    button->setStyleSheet(
        QString("QToolButton { background: %1; min-width: 18px; }").arg(shown().name()));
    connect(button, &QToolButton::clicked, this, [this, shown, key, label, max] {
        auto* picker = new QColorDialog(shown(), this);
        picker->setObjectName("colour_picker");
        picker->setAttribute(Qt::WA_DeleteOnClose);
        connect(
            picker, &QColorDialog::colorSelected, this, [this, key, label, max](const QColor& c) {
                const auto linear = [max](double srgb) {
                    return std::min(max, srgb_to_linear(srgb));
                };
                commit(key, json::array({linear(c.redF()), linear(c.greenF()), linear(c.blueF())}),
                       label);
            });
        picker->open();
    });
    row->layout()->addWidget(button);
}

void PropertyPanel::add_choice(const QString& label, const std::string& key,
                               const std::string& fallback, const QStringList& choices,
                               const std::function<void(const std::string&)>& on_choose) {
    auto* box = new QComboBox(m_form_widget);
    box->setObjectName(QString::fromStdString("field:" + key));
    box->addItems(choices);
    const json* v = value_at(key);
    box->setCurrentText(
        QString::fromStdString(v && v->is_string() ? v->get<std::string>() : fallback));
    connect(box, &QComboBox::activated, this, [this, box, key, label, on_choose] {
        const std::string chosen = box->currentText().toStdString();
        if (on_choose) {
            on_choose(chosen);
        } else {
            commit(key, chosen, label);
        }
    });
    m_form->addRow(label, box);
}

void PropertyPanel::add_flag(const QString& label, const std::string& key,
                             const QString& when_absent) {
    const json* v = value_at(key);
    const QString current =
        v && v->is_boolean() ? (v->get<bool>() ? tr("yes") : tr("no")) : when_absent;
    QStringList choices{tr("yes"), tr("no")};
    if (when_absent == tr("auto")) choices.prepend(when_absent);
    add_choice(label, key, current.toStdString(), choices,
               [this, key, label](const std::string& chosen) {
                   const json* here = value_at("");
                   json element = here ? *here : json::object();
                   if (chosen == tr("auto").toStdString()) {
                       element.erase(key);
                   } else {
                       element[key] = chosen == tr("yes").toStdString();
                   }
                   commit("", element, label);
               });
}

void PropertyPanel::add_text(const QString& label, const std::string& key,
                             const std::string& fallback) {
    auto* edit = new QLineEdit(m_form_widget);
    edit->setObjectName(QString::fromStdString("field:" + key));
    const json* v = value_at(key);
    edit->setText(QString::fromStdString(v && v->is_string() ? v->get<std::string>() : fallback));
    connect(edit, &QLineEdit::editingFinished, this,
            [this, edit, key, label] { commit(key, edit->text().toStdString(), label); });
    m_form->addRow(label, edit);
}

void PropertyPanel::add_formula(
    const QString& label, const std::string& key, const std::string& fallback,
    const std::function<std::optional<std::string>(const std::string&)>& check) {
    // Named copies, not a structured binding: lambdas capture them (clang 14, which builds the
    // sanitizer stage, cannot capture structured bindings).
    const CheckedLineEdit field =
        make_checked_line_edit(m_form_widget, key, "formula_error:" + key);
    QWidget* box = field.box;
    QLineEdit* edit = field.edit;
    QLabel* problem = field.problem;
    const json* current = value_at(key);
    edit->setText(QString::fromStdString(
        current && current->is_string() ? current->get<std::string>() : fallback));
    // Checked on every keystroke (muparser parses a short formula in microseconds).
    auto validate = [edit, problem, check] {
        const auto reason = check(edit->text().toStdString());
        problem->setText(reason ? QString::fromStdString(*reason) : QString());
        problem->setVisible(reason.has_value());
        return !reason;
    };
    connect(edit, &QLineEdit::textEdited, this, [validate] { validate(); });
    connect(edit, &QLineEdit::editingFinished, this, [this, edit, key, label, validate] {
        if (validate()) commit(key, edit->text().toStdString(), label);
    });
    m_form->addRow(label, box);
}

void PropertyPanel::add_number_list(const QString& label, const std::string& key,
                                    const json& fallback, size_t max_count) {
    // Named copies, not a structured binding: lambdas capture them (clang 14, which builds the
    // sanitizer stage, cannot capture structured bindings).
    const CheckedLineEdit field = make_checked_line_edit(m_form_widget, key, "list_error:" + key);
    QWidget* box = field.box;
    QLineEdit* edit = field.edit;
    QLabel* problem = field.problem;
    const json* current = value_at(key);
    QStringList shown;
    for (const json& x : (current && current->is_array() ? *current : fallback)) {
        if (x.is_number()) shown << QString::fromStdString(format_number(x.get<double>()));
    }
    edit->setText(shown.join(", "));
    // The numbers, or nothing (with the reason shown) when the text is not a list of them.
    // Each number read as a number field reads one (no stray text stripped, no locale).
    const ParamSpec element =
        number_param(key, 0.0).at_least(-kMaxSceneNumber).at_most(kMaxSceneNumber);
    auto parse = [edit, problem, max_count, element]() -> std::optional<json> {
        json values = json::array();
        QString reason;
        for (const QString& part : edit->text().split(',')) {
            const ParsedNumber x = parse_number(part.trimmed(), element);
            if (!x.value) {
                reason = x.problem;
                break;
            }
            values.push_back(*x.value);
        }
        if (reason.isEmpty() && (values.empty() || values.size() > max_count)) {
            reason = tr("give 1 to %1 numbers separated by commas").arg(max_count);
        }
        problem->setText(reason);
        problem->setVisible(!reason.isEmpty());
        return reason.isEmpty() ? std::optional<json>(values) : std::nullopt;
    };
    connect(edit, &QLineEdit::textEdited, this, [parse] { (void)parse(); });
    connect(edit, &QLineEdit::editingFinished, this, [this, key, label, parse] {
        if (const auto values = parse()) commit(key, *values, label);
    });
    m_form->addRow(label, box);
}

void PropertyPanel::add_param(const ParamSpec& p, const std::string& prefix) {
    const QString label = QString::fromStdString(p.label);
    const std::string key = prefix + p.key;
    const json& d = p.fallback;
    switch (p.kind) {
        case ParamKind::WholeNumber:
        case ParamKind::Number:
        case ParamKind::Fraction:
            add_number(label, p, key);
            break;
        case ParamKind::Boolean:
            add_flag(label, key, d.is_boolean() && d.get<bool>() ? tr("yes") : tr("no"));
            break;
        case ParamKind::Choice:
            add_choice(label, key, d.get<std::string>(), to_qt(p.choices));
            break;
        case ParamKind::String:
            add_text(label, key, d.is_string() ? d.get<std::string>() : "");
            break;
        case ParamKind::Colour:
            add_vec3(label, key, as_triple(d), 0, 1e6, p.doc, true);
            break;
        case ParamKind::Albedo:
            add_vec3(label, key, as_triple(d), 0, 1, p.doc, true);
            break;
        case ParamKind::Point:
            add_vec3(label, key, d.is_null() ? json::array({0, 0, 0}) : d, -1e6, 1e6, p.doc);
            break;
        case ParamKind::Direction:
            add_vec3(label, key, d.is_null() ? json::array({0, 0, -1}) : d, -1e6, 1e6, p.doc);
            break;
        case ParamKind::Object:
        case ParamKind::Array:
            break;  // nested things have forms of their own
    }
}

void PropertyPanel::build_declared(const ElementSpec& spec, const std::vector<std::string>& skip,
                                   const std::string& prefix) {
    std::string group;
    for (const ParamSpec& p : spec.params) {
        if (p.label.empty() || std::find(skip.begin(), skip.end(), p.key) != skip.end()) continue;
        if (p.group != group) {
            group = p.group;
            add_heading(QString::fromStdString(group));
        }
        add_param(p, prefix);
    }
}

void PropertyPanel::build_camera() {
    add_heading(tr("Camera"));
    // The camera takes look_at or direction; the form edits the one the file gives.
    build_declared(camera_spec(), {value_at("look_at") ? "direction" : "look_at"});
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
}

void PropertyPanel::build_surface(const QString& label, const std::string& key) {
    const json* s = value_at(key);
    const std::string shape = s ? s->value("shape", "sphere") : "sphere";
    // Switching the shape replaces the whole surface (a flat one has no radius), keeping
    // what carries over.
    const double diameter = value_at("diameter") ? value_at("diameter")->get<double>() : 1.0;
    QStringList shapes;
    for (const std::string& name : kSurfaceShapeNames) shapes << QString::fromStdString(name);
    add_choice(label, key + "/shape", shape, shapes,
               [this, key, label, diameter](const std::string& chosen) {
                   commit(key, surface_of_shape(chosen, value_at(key), diameter), label);
               });
    // The shape's declared fields, labelled with the face they belong to; a new radius is
    // twice the diameter.
    const ElementSpec* declared = surface_spec(shape);
    const auto add_field = [&](const std::string& field, const json& shown) {
        if (!declared || !declared->find(field)) return;
        ParamSpec p = declared->param(field);
        p.label = label.toStdString() + " " + p.label;
        if (p.fallback.is_null()) p.fallback = shown;
        add_param(p, key + "/");
    };
    add_field("radius", 2.0 * diameter);
    add_field("k", 0.0);
    if (shape == "asphere") {
        add_number_list(label + tr(" A4, A6, ... A16"), key + "/coefficients", json::array({0.0}),
                        7);
    }
    if (shape == "sag") {
        add_formula(label + tr(" z(r) or z(x, y)"), key + "/formula", "r^2/100",
                    SagFormulaSurface::check);
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
    // A colour (D65-based) or a named spectrum; switching rewrites the light's keys.
    const json* spectrum = value_at(prefix + "spectrum");
    std::string kind = "colour";
    if (spectrum && spectrum->is_string()) kind = "d65";
    if (spectrum && spectrum->is_object())
        kind = spectrum->contains("blackbody") ? "blackbody" : "line";
    const std::string owner = prefix.empty() ? "" : prefix.substr(0, prefix.size() - 1);
    add_choice(tr("Spectrum"), prefix + "spectrum", kind, {"colour", "d65", "blackbody", "line"},
               [this, owner](const std::string& chosen) {
                   json element = *value_at(owner);
                   element.erase("color");
                   element.erase("spectrum");
                   if (chosen == "d65") element["spectrum"] = "d65";
                   if (chosen == "blackbody") element["spectrum"] = {{"blackbody", 3000}};
                   if (chosen == "line") element["spectrum"] = {{"line", 532}};
                   commit(owner, element, tr("spectrum"));
               });
    if (kind == "colour")
        add_vec3(tr("Colour"), prefix + "color", json::array({1, 1, 1}), 0, 1e6, "", true);
    if (kind == "blackbody")
        add_number(tr("Temperature (K)"), prefix + "spectrum/blackbody", 3000, 500, 100000);
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
