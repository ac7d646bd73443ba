#include "image_export.h"

#include <QEventLoop>
#include <QProgressDialog>
#include <QThread>
#include <QTimer>
#include <atomic>
#include <memory>

#include "image/image_io.h"
#include "render/render_session.h"
#include "scene/render_tone_map.h"
#include "util/output_path.h"

namespace lenslab::gui {

namespace {
constexpr int kExportProgressSteps = 1000;
}  // namespace

bool export_scene_image(const Scene& scene, const QString& path, QWidget* parent, QString* error) {
    const std::string file = path.toStdString();
    try {
        check_output_file(file);  // before the render, not after
        if (!is_supported_image_path(file))
            throw std::runtime_error(file + ": unknown image format (use .png or .exr)");
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    std::atomic<double> done{0};
    RenderControl control([&done](double fraction) { done = fraction; });
    RenderResult result;
    QString failure;
    std::unique_ptr<QThread> worker(QThread::create([&] {
        try {
            result = render_scene(scene, control);
        } catch (const std::exception& e) {
            failure = QString::fromStdString(e.what());
        }
    }));

    QProgressDialog dialog(QObject::tr("Rendering %1 x %2 for export...")
                               .arg(scene.render.width)
                               .arg(scene.render.height),
                           QObject::tr("Cancel"), 0, kExportProgressSteps, parent);
    dialog.setObjectName("export_progress");
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setMinimumDuration(0);
    dialog.setAutoClose(false);
    dialog.setAutoReset(false);
    QObject::connect(&dialog, &QProgressDialog::canceled, [&control] { control.cancel(); });
    QTimer tick;
    QObject::connect(&tick, &QTimer::timeout,
                     [&] { dialog.setValue(int(done.load() * (kExportProgressSteps - 1))); });
    QEventLoop loop;
    QObject::connect(worker.get(), &QThread::finished, &loop, &QEventLoop::quit);
    dialog.show();
    tick.start(50);
    worker->start();
    loop.exec();
    worker->wait();
    tick.stop();
    dialog.hide();

    QString message = failure;
    if (message.isEmpty() && (result.cancelled || control.cancelled()))
        message = QObject::tr("export cancelled: %1 not written").arg(path);
    if (message.isEmpty()) {
        try {
            write_image(result.film, file, tone_map_for(scene.render));
            return true;
        } catch (const std::exception& e) {
            message = QString::fromStdString(e.what());
        }
    }
    if (error) *error = message;
    return false;
}

}  // namespace lenslab::gui
