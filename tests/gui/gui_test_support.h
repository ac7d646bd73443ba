#pragma once
// What the editor's tests do as a user would, shared by them: open the small scene, type
// into a form's number field, wait for a frame rendered after an edit.

#include <QElapsedTimer>
#include <QString>
#include <QtTest>
#include <memory>

#include "main_window.h"
#include "number_field.h"
#include "property_panel.h"
#include "render_controller.h"

namespace lenslab::gui::testing {

inline const QString kSmallScene = QStringLiteral(LENSLAB_TEST_DATA "/gui/small_scene.json");

// The property panel's number field for the parameter `name`.
inline NumberField* field(MainWindow& w, const QString& name) {
    return w.panel()->findChild<NumberField*>("field:" + name);
}

// Sets a number field as a user would (its text, then leaving the field).
inline void type_value(NumberField* box, double v) {
    box->setText(format_shown(v));
    emit box->editingFinished();
}

// Waits for the first pass of a render started after now; its integrator's name, or "" when
// none came. frame_ready is emitted on the render thread; a QSignalSpy would record it there
// (a direct connection) while this thread reads its list, so frames are counted here, on this
// thread, through a queued connection, into a shared result: a frame already queued when this
// returns (and disconnects) is still delivered later, and must not write into a dead stack
// frame (UBSan caught it).
inline QString integrator_of_fresh_frame(MainWindow& w, int timeout_ms = 20000) {
    const auto integrator = std::make_shared<QString>();
    const QMetaObject::Connection watch = QObject::connect(
        w.renderer(), &RenderController::frame_ready, &w,
        [integrator](const QImage&, int passes, qint64, double, const QString& name) {
            if (passes == 1 && integrator->isEmpty()) *integrator = name;
        },
        Qt::QueuedConnection);
    QElapsedTimer t;
    t.start();
    while (integrator->isEmpty() && t.elapsed() < timeout_ms) QTest::qWait(5);
    QObject::disconnect(watch);
    return *integrator;
}

// Waits for a frame rendered from the scene as it is now (pass 1 after a restart).
inline bool wait_for_fresh_frame(MainWindow& w, int timeout_ms = 20000) {
    return !integrator_of_fresh_frame(w, timeout_ms).isEmpty();
}

}  // namespace lenslab::gui::testing
