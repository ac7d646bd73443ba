// The property panel's field factory: one form row per parameter (number, vector, colour, choice,
// flag, text, formula, number list), each committing its edit through the document.

#include <QColorDialog>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSlider>
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

namespace {

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
    // A colour's boxes are its red, green and blue bands (typing in one tints it): labelled.
    static const char* const kBands[3] = {"R", "G", "B"};
    static const char* const kBandRanges[3] = {
        "red band, 585 nm and above", "green band, 490 to 585 nm", "blue band, below 490 nm"};
    for (int i = 0; i < 3; ++i) {
        fields[i] = add_number_field(row, component, key + "." + "xyz"[i], label);
        fields[i]->setValue(value.is_array() && value.size() == 3 && value[i].is_number()
                                ? value[i].get<double>()
                                : 0.0);
        if (colour) {
            auto* band = new QLabel(QString::fromLatin1(kBands[i]), row);
            band->setObjectName(QString::fromStdString("band:" + key + "." + kBands[i]));
            band->setToolTip(tr(kBandRanges[i]));
            h->addWidget(band);
        }
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
        case ParamKind::Array:
            // An array of numbers: a comma-separated list (one 0 to start where it needs one).
            if (p.most_count > 0) {
                const json start = json::array_t(p.least_count, json(0.0));
                add_number_list(label, key, d.is_array() ? d : start, p.most_count);
            }
            break;  // other arrays have forms of their own
        case ParamKind::Object:
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

}  // namespace lenslab::gui
