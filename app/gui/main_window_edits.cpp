// The editor's edits of the scene's elements (Add, Import lens, Add floor, Add atmosphere,
// Duplicate, Delete): the edits themselves are pure functions of the scene layer
// (scene/element_edits.h); here they are placed in the view, applied and selected.

#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>

#include "analysis/figures/ray_diagram.h"
#include "detector_dock.h"
#include "image/image_io.h"
#include "image_export.h"
#include "json_pointer.h"
#include "main_window.h"
#include "number_field.h"
#include "optimise_dialog.h"
#include "placement.h"
#include "property_panel.h"
#include "ray_diagram_dock.h"
#include "render/camera.h"
#include "render_controller.h"
#include "scene/element_edits.h"
#include "scene/lens_file_import.h"
#include "scene/light_spec.h"
#include "scene/medium.h"
#include "scene/object_types.h"
#include "scene/scene_json.h"
#include "scene_document.h"
#include "scene_tree.h"
#include "section_widget.h"
#include "viewport.h"

namespace lenslab::gui {

using nlohmann::json;

namespace {

// Scene units per millimetre that make a lens `diameter_mm` across a quarter of the scene's
// size (a 1, 2 or 5 times a power of ten), when the lens in millimetres would be larger than
// the whole scene; 0 when it fits as it is (or the scene is empty).
double import_fit_scale(const Scene& scene, double diameter_mm) {
    if (scene.objects.empty() || !(diameter_mm > 0)) return 0;
    const Vec3 size = scene.bounds().extent();
    const double scene_size = std::max({size.x, size.y, size.z});
    if (!(scene_size > 0) || diameter_mm <= scene_size) return 0;
    return diagram_round_length(0.25 * scene_size / diameter_mm);
}

// Asks how to bring the lens in; Ask back for Cancel.
MainWindow::ImportLengths ask_import_lengths(QWidget* parent, double diameter_mm, double fit) {
    QMessageBox box(QMessageBox::Question, QObject::tr("Import lens"),
                    QObject::tr("The lens is %1 mm across, larger than this whole scene, which "
                                "declares no length unit. Scale it to fit (1 mm becomes %2 "
                                "scene units), or keep 1 unit = 1 mm?")
                        .arg(format_shown(diameter_mm), format_shown(fit)),
                    QMessageBox::Cancel, parent);
    box.setObjectName("import_scale_question");
    QPushButton* scaled = box.addButton(QObject::tr("Scale to fit"), QMessageBox::AcceptRole);
    scaled->setObjectName("import_scale_fit");
    QPushButton* mm = box.addButton(QObject::tr("Keep millimetres"), QMessageBox::AcceptRole);
    mm->setObjectName("import_scale_mm");
    box.setDefaultButton(scaled);
    box.exec();
    if (box.clickedButton() == scaled) return MainWindow::ImportLengths::FitScene;
    if (box.clickedButton() == mm) return MainWindow::ImportLengths::Millimetres;
    return MainWindow::ImportLengths::Ask;
}

// How far `example` (an object as its declaration gives it, or a light) must move so that it
// rests on the surface the view's centre looks at, on the camera's side, touching it with
// its bounding box; a light, or a view of nothing, puts it 3 units ahead of the camera.
// (New objects all landed 3 units ahead, often inside what was there.)
Vec3 placement(const Scene& scene, const json& example) {
    const Vec3 ahead = scene.camera.position + scene.camera.direction * 3.0;
    Scene alone;
    try {
        if (!example.contains("type") || find_light_spec(example["type"].get<std::string>()))
            return ahead;
        alone = scene_from_json(json{{"camera", {{"position", {0, 0, 5}}, {"look_at", {0, 0, 0}}}},
                                     {"objects", json::array({example})}});
    } catch (const std::exception&) {
        return ahead;
    }
    const Aabb box = alone.bounds();
    const Camera camera(scene.camera, scene.render.width, scene.render.height);
    const Ray centre = camera.generate_ray(scene.render.width / 2.0, scene.render.height / 2.0);
    if (box.empty()) return ahead;
    return resting_offset(scene, box, centre).value_or(ahead - box.centre());
}

}  // namespace

void MainWindow::add_element(const QString& kind) {
    const json& document = m_document->json();
    const std::string type = kind.toStdString();
    const std::string list = element_list(type);
    const ElementSpec* spec = element_spec(list, type);
    if (!spec) return;
    const ElementEdit edit =
        with_element(document, list,
                     placed_element(document, list, spec->example,
                                    placement(m_document->scene(), spec->example)));
    if (!apply_element_edit(edit, tr("Add %1").arg(kind))) return;
    if (list == "objects") {
        // It rests where the view's centre looks; the next click in the view moves it there.
        m_viewport->arm_placement(
            int(split_pointer(QString::fromStdString(edit.pointer))[1].toInt()));
        show_message(
            tr("Click in the 3-D view to place the new %1 (Esc: leave it here).").arg(kind));
    }
}

bool MainWindow::apply_element_edit(const ElementEdit& edit, const QString& label) {
    QString error;
    if (!m_document->apply(edit.scene, label, &error)) {
        show_message(error);
        return false;
    }
    m_tree->select_pointer(QString::fromStdString(edit.pointer));
    if (edit.pointer.empty()) m_panel->show_pointer(QString());
    return true;
}

bool MainWindow::import_lens(const QString& path, QString* error, ImportLengths lengths) {
    const std::string file = path.toStdString();
    const std::string name = QFileInfo(path).completeBaseName().toStdString();
    // Scene units per millimetre: the scene's declared unit, else millimetres.
    const json& scene_json = m_document->json();
    double scale = 1.0 / scene_json.value("length_unit_mm", 1.0);
    ImportedLens lens;
    try {
        lens = import_lens_file(file, name, scale);
        // A lens that would dwarf a scene of no declared unit (lengths of about 1) is
        // offered scaled to a quarter of the scene's size.
        const double fit =
            scene_json.contains("length_unit_mm")
                ? 0.0
                : import_fit_scale(m_document->scene(), lens.group.value("diameter", 0.0));
        if (fit > 0 && lengths == ImportLengths::Ask && !error) {
            lengths = ask_import_lengths(this, lens.group.value("diameter", 0.0), fit);
            if (lengths == ImportLengths::Ask) return false;  // cancelled
        }
        if (fit > 0 && lengths == ImportLengths::FitScene) {
            scale = fit;
            lens = import_lens_file(file, name, scale);
        }
    } catch (const std::exception& e) {
        if (error) {
            *error = QString::fromStdString(e.what());
        } else {
            QMessageBox::warning(this, tr("Import lens"), QString::fromStdString(e.what()));
        }
        return false;
    }
    const json& document = m_document->json();
    // The lens_group as `lenslab import` writes it (vertex at the origin, along +z).
    const json group = json::parse(imported_scene_json(lens, file)["objects"][0].dump());
    const ElementEdit edit = with_element(
        document, "objects",
        placed_element(document, "objects", group, placement(m_document->scene(), group)));
    QString why;
    if (!m_document->apply(edit.scene, tr("Import lens"), &why)) {
        if (error) {
            *error = why;
        } else {
            show_message(why);
        }
        return false;
    }
    m_tree->select_pointer(QString::fromStdString(edit.pointer));
    QString note = tr("Imported %1: %2 element(s), ")
                       .arg(QFileInfo(path).fileName())
                       .arg(lens.element_lines.size());
    note += scale == 1.0 ? tr("lengths in mm")
                         : tr("1 mm made %1 scene units").arg(format_shown(scale));
    if (!lens.warnings.empty())
        note += tr("; %1 line(s) passed over: %2")
                    .arg(lens.warnings.size())
                    .arg(QString::fromStdString(lens_file_warnings_text(lens, file)).trimmed());
    show_message(note);
    return true;
}

void MainWindow::add_floor() {
    const json& document = m_document->json();
    apply_element_edit(
        with_element(document, "objects", floor_under(m_document->scene(), document)),
        tr("Add floor"));
}

void MainWindow::add_atmosphere() {
    if (!m_document->json().contains("atmosphere")) {
        QString error;
        if (!m_document->apply(with_atmosphere(m_document->json()), tr("Add atmosphere"), &error)) {
            show_message(error);
            return;
        }
    }
    m_tree->select_pointer("/atmosphere");
}

void MainWindow::duplicate_selected() {
    const auto edit = with_duplicate(m_document->json(), m_tree->selected_pointer().toStdString());
    if (edit) apply_element_edit(*edit, tr("Duplicate"));
}

void MainWindow::delete_selected() {
    const auto edit = without_element(m_document->json(), m_tree->selected_pointer().toStdString());
    if (edit) apply_element_edit(*edit, tr("Delete"));
}

}  // namespace lenslab::gui
