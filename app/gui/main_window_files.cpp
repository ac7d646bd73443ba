// The editor's files: opening, saving, asking before losing changes, exporting the image, the
// recent files.

#include <QCloseEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

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

constexpr int kMaxRecent = 8;

}  // namespace

bool MainWindow::open_file(const QString& path, QString* error, bool as_copy) {
    QString message;
    if (!m_document->open(path, &message, as_copy)) {
        if (error)
            *error = message;
        else
            show_open_error(message);
        show_message(message);
        return false;
    }
    if (!as_copy) remember_recent(path);
    // What the scene is about first, where the file says.
    m_tree->select_pointer(m_document->json().contains("description") ? "/description" : "/camera");
    if (m_document->camera_made()) {
        // A lens file: the section shows its lenses at once; the 3-D view has a camera made
        // for it, and is dark when the file has no light.
        const bool lit = !m_document->scene().lights().empty() ||
                         !m_document->scene().render.background.is_black();
        show_message(
            tr("%1 has no camera: one was made to show the whole scene (Save keeps "
               "it)%2")
                .arg(QFileInfo(path).fileName(),
                     lit ? QString() : tr("; no lights either: add one to see it in 3-D")));
        show_view("section");
    }
    return true;
}

void MainWindow::show_open_error(const QString& message) {
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open scene"), message,
                                QMessageBox::Ok, this);
    box->setObjectName("open_error");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

bool MainWindow::save_file(const QString& path, QString* error) {
    QString message;
    if (!m_document->save(path, &message)) {
        if (error)
            *error = message;
        else
            QMessageBox::warning(this, tr("Cannot save"), message);
        return false;
    }
    remember_recent(path);
    return true;
}

bool MainWindow::save() {
    return m_document->path().isEmpty() ? save_as() : save_file(m_document->path());
}

bool MainWindow::save_as() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save scene"), m_document->path(),
                                                      tr("Scenes (*.json)"));
    return !path.isEmpty() && save_file(path);
}

bool MainWindow::maybe_save() {
    if (!m_document->is_modified()) return true;
    const auto answer =
        QMessageBox::question(this, tr("Unsaved changes"), tr("Save the changes to this scene?"),
                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (maybe_save()) {
        QSettings("lenslab", "lenslab-gui").setValue("geometry", saveGeometry());
        m_renderer->stop_rendering();
        event->accept();
    } else {
        event->ignore();
    }
}

void MainWindow::export_image() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export image"), "lenslab.png",
                                                      tr("Images (*.png *.exr)"));
    if (!path.isEmpty()) export_image_to(path);
}

bool MainWindow::export_image_to(const QString& path, QString* error) {
    // The view's render waits meanwhile (the export gets every core) and then goes on.
    m_renderer->set_paused(true);
    QString message;
    const bool written = export_scene_image(m_document->scene(), path, this, &message);
    m_renderer->set_paused(false);
    if (!written) {
        if (error)
            *error = message;
        else
            QMessageBox::warning(this, tr("Cannot export"), message);
        show_message(message);
        return false;
    }
    show_message(tr("wrote %1").arg(path));
    return true;
}

void MainWindow::remember_recent(const QString& path) {
    QSettings settings("lenslab", "lenslab-gui");
    QStringList recent = settings.value("recent").toStringList();
    recent.removeAll(QFileInfo(path).absoluteFilePath());
    recent.prepend(QFileInfo(path).absoluteFilePath());
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue("recent", recent);
    update_recent_menu();
}

void MainWindow::update_recent_menu() {
    m_recent_menu->clear();
    for (const QString& path : QSettings("lenslab", "lenslab-gui").value("recent").toStringList()) {
        m_recent_menu->addAction(path, this, [this, path] {
            if (maybe_save()) open_file(path);
        });
    }
    m_recent_menu->setEnabled(!m_recent_menu->isEmpty());
}

}  // namespace lenslab::gui
