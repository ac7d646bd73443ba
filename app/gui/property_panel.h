#pragma once
// Edits what is selected in the scene tree: a form of typed fields (numbers with their valid
// ranges, vectors, colours, choices) built for the kind of element selected: camera, render
// settings, atmosphere, material, sphere, triangle, disc, rectangle (and the detector flag of these
// three), lens (both forms, every surface shape: flat, sphere, conic, asphere, typed sag formula),
// implicit solid, light. Formulas are checked as they are typed: the reason one would be refused
// shows next to the field at once, and the field commits only a formula that parses. Each committed
// field is one undoable edit; a value the scene reader refuses is not applied and the reason shows
// under the form.

#include <QLabel>
#include <QPointer>
#include <QWidget>
#include <array>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/param_spec.h"

class QFormLayout;

namespace lenslab::gui {

class SceneDocument;
class NumberField;

class PropertyPanel : public QWidget {
    Q_OBJECT

public:
    PropertyPanel(SceneDocument* document, QWidget* parent = nullptr);

    // Shows the fields of the element at `pointer` ("/objects/2"), or nothing for "".
    void show_pointer(const QString& pointer);
    const QString& pointer() const { return m_pointer; }
    QString error_text() const { return m_error->text(); }

signals:
    void edit_refused(const QString& message);
    // An edit of the whole document (a material renamed, added, made unique) moved what
    // should be selected: the tree selects `pointer`.
    void pointer_requested(const QString& pointer);
    // The form's Remove button (the atmosphere's): the selected element goes, as Edit ▸ Delete
    // removes it.
    void delete_requested();

private:
    void rebuild();
    void build_form();
    // Commits `value` at `key` (a pointer relative to the selected element).
    void commit(const std::string& key, const nlohmann::json& value, const QString& label);

    // Field builders; `key` is relative to the selected element, `fallback` is shown when
    // the file leaves the key out (the reader's default).
    void add_number(const QString& label, const std::string& key, double fallback, double min,
                    double max);
    // A number field for declared parameter `p`, at `key` (p's key with its prefix).
    void add_number(const QString& label, const ParamSpec& p, const std::string& key);
    // A field whose refusals show under the form and in the status bar.
    NumberField* add_number_field(QWidget* parent, const ParamSpec& p, const std::string& key,
                                  const QString& label);
    void add_integer(const QString& label, const std::string& key, long long fallback,
                     long long min, long long max);
    // `colour`: an RGB triple, with a button that opens a colour picker beside it.
    void add_vec3(const QString& label, const std::string& key, const nlohmann::json& fallback,
                  double min = -1e6, double max = 1e6, const std::string& doc = "",
                  bool colour = false);
    // The swatch button beside a colour's three fields; the picker commits linear RGB.
    void add_colour_button(QWidget* row, const std::array<NumberField*, 3>& fields,
                           const std::string& key, const QString& label, double max);
    // `on_choose` replaces the default commit (the chosen string at `key`).
    void add_choice(const QString& label, const std::string& key, const std::string& fallback,
                    const QStringList& choices,
                    const std::function<void(const std::string&)>& on_choose = {});
    // A true/false key as a choice of yes and no; `when_absent` is shown while the key is
    // absent ("auto" adds a choice that removes it).
    void add_flag(const QString& label, const std::string& key, const QString& when_absent);
    void add_text(const QString& label, const std::string& key, const std::string& fallback);
    // A formula field: `check` returns why a text would be refused (shown under the field
    // while typing, in a label named "formula_error:" + key), or nothing.
    void add_formula(const QString& label, const std::string& key, const std::string& fallback,
                     const std::function<std::optional<std::string>(const std::string&)>& check);
    // Comma-separated numbers committed as a JSON array (asphere coefficients).
    void add_number_list(const QString& label, const std::string& key,
                         const nlohmann::json& fallback, size_t max_count);
    void add_heading(const QString& text);
    // A declared parameter's field (param_spec.h): its label, fallback, range and choices.
    void add_param(const ParamSpec& p, const std::string& prefix = "");
    // Every parameter of `spec` the editor shows (those with a label) but `skip`, under the
    // declared headings; `prefix` is where the element is, relative to the selected one.
    void build_declared(const ElementSpec& spec, const std::vector<std::string>& skip = {},
                        const std::string& prefix = "");

    void build_camera();
    void build_description();
    void build_render();
    void build_atmosphere();
    // A medium object's fields (scene/medium.h) at `prefix`: "" for the atmosphere itself,
    // "medium/" for a shape's.
    void build_medium_fields(const std::string& prefix);
    void build_material(const std::string& prefix);
    // The glass of the material at `material_key`: an editable list of every glass lenslab
    // knows, searched as one types; `current` is the glass named now (empty: an index).
    void add_glass_choice(const std::string& key, const std::string& material_key,
                          const std::string& current);
    // The table's own entry (/materials/NAME): its name and the buttons that add, copy and
    // delete materials (scene/material_edits.h).
    void build_material_entry();
    // Applies a whole-document edit (material_edits.h), or shows why it was refused; then
    // asks for `select` to be selected.
    template <class Edit>
    void apply_material_edit(const QString& label, const Edit& edit);
    void build_object();
    void build_lens();
    void build_lens_group();
    void build_material_ref(const QString& label, const std::string& key);
    void build_surface(const QString& label, const std::string& key);
    void build_implicit();
    void build_flat(const std::string& type);  // disc, rectangle
    void build_detector();
    // A closed shape's medium: none, or its coefficients (scene/medium.h).
    void build_medium();
    void build_light();
    void build_spectrum(const std::string& prefix);
    // A material's gradient index (docs/grin.md): its profile and that profile's parameters.
    void build_grin(const std::string& prefix);

    const nlohmann::json* value_at(const std::string& key) const;

    SceneDocument* m_document;
    QString m_pointer;
    QPointer<QWidget> m_form_widget;
    QFormLayout* m_form = nullptr;
    QLabel* m_error;
};

}  // namespace lenslab::gui
