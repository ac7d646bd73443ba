// The editor's edits of the scene's elements (Add, Import lens, Add floor, Add atmosphere,
// Duplicate, Delete): the edits themselves are pure functions of the scene layer
// (scene/element_edits.h); here they are placed in the view, applied and selected.

#include <QFileInfo>
#include <QMessageBox>

#include "detector_dock.h"
#include "image/image_io.h"
#include "image_export.h"
#include "json_pointer.h"
#include "main_window.h"
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

bool MainWindow::import_lens(const QString& path, QString* error) {
    const std::string file = path.toStdString();
    ImportedLens lens;
    try {
        lens = import_lens_file(file, QFileInfo(path).completeBaseName().toStdString());
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
    QString note = tr("Imported %1: %2 element(s), lengths in mm")
                       .arg(QFileInfo(path).fileName())
                       .arg(lens.element_lines.size());
    const double unit_mm = edit.scene.value("length_unit_mm", 1.0);
    if (unit_mm != 1.0) note += tr(" (the scene's unit is %1 mm)").arg(unit_mm);
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
