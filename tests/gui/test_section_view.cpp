// The section view: dragging a lens with real mouse events moves it by one undoable edit
// while the rays follow, the drawing exports as SVG, and `lenslab-gui --screenshot FILE
// --view section` writes a picture of the window showing it.

#include <QComboBox>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>

#include "main_window.h"
#include "render_controller.h"
#include "scene_document.h"
#include "scene_tree.h"
#include "section_widget.h"

using lenslab::DiagramPoint;
using lenslab::gui::MainWindow;
using nlohmann::json;

namespace {

// Where the lens's cross-section is drawn: the middle of its outline's points.
QPointF drawn_centre(const lenslab::gui::SectionWidget& view, int object) {
    for (const auto& o : view.section().objects) {
        if (o.object != object) continue;
        double z = 0, y = 0;
        for (const DiagramPoint& p : o.curves.at(0).points) z += p.z, y += p.y;
        const double n = double(o.curves.at(0).points.size());
        return view.to_widget({z / n, y / n});
    }
    return {-1, -1};
}

// Whether two polylines are the same points.
bool same_polyline(const std::vector<lenslab::Vec3>& a, const std::vector<lenslab::Vec3>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].z != b[i].z) return false;
    }
    return true;
}

}  // namespace

class TestSectionView : public QObject {
    Q_OBJECT

private slots:
    void dragging_the_lens_moves_it_and_undo_restores_it() {
        MainWindow w;  // the default scene; objects[1] is the glass lens
        QVERIFY(w.show_view("section"));
        w.tree()->select_pointer("/objects/1");
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* view = w.section_view();
        QCOMPARE(view->selected_object(), 1);
        const json before = w.document()->json();
        const auto rays_before = view->section().rays;
        QVERIFY(rays_before.size() >= 15);

        const QPoint press = drawn_centre(*view, 1).toPoint();
        QVERIFY(view->rect().contains(press));
        const QPoint shift(60, 0);  // to the right: along the plane's u
        const lenslab::Vec3 u = view->section().plane.u;
        const lenslab::DiagramView placement = view->placement();
        // Frames while the button is down are drafts, a quarter of the preview each way.
        const auto widest = std::make_shared<int>(0);
        const QMetaObject::Connection watch = QObject::connect(
            w.renderer(), &lenslab::gui::RenderController::frame_ready, &w,
            [widest](const QImage& image) { *widest = std::max(*widest, image.width()); },
            Qt::QueuedConnection);
        QTest::mousePress(view, Qt::LeftButton, {}, press);
        for (int i = 1; i <= 6; ++i) QTest::mouseMove(view, press + shift * i / 6);
        QTRY_VERIFY_WITH_TIMEOUT(*widest > 0, 20000);
        QVERIFY2(*widest <= 160, qPrintable(QString::number(*widest)));
        QObject::disconnect(watch);
        // The rays follow while the button is still down.
        QVERIFY(w.document()->json() != before);
        QVERIFY(view->section().rays.size() != rays_before.size() ||
                !same_polyline(view->section().rays[0].points, rays_before[0].points));
        QTest::mouseRelease(view, Qt::LeftButton, {}, press + shift);

        const json centre = w.document()->json()["objects"][1]["center"];
        const json old_centre = before["objects"][1]["center"];
        const double moved = shift.x() / placement.scale;
        for (int k = 0; k < 3; ++k) {
            const double expected = old_centre[k].get<double>() + u[k] * moved;
            QVERIFY2(std::abs(centre[k].get<double>() - expected) < 1e-9 + 1e-3 * moved,
                     qPrintable(QString::fromStdString(centre.dump())));
        }
        QCOMPARE(w.document()->undo_stack()->count(), 1);
        QVERIFY(w.document()->undo_stack()->text(0).contains("glass lens"));
        // Nothing else moved.
        json rest = w.document()->json();
        rest["objects"][1] = before["objects"][1];
        QCOMPARE(rest, before);

        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->json(), before);
        QCOMPARE(view->section().rays.size(), rays_before.size());
        QVERIFY(same_polyline(view->section().rays[0].points, rays_before[0].points));
    }

    void a_click_selects_and_the_drawing_exports_as_svg() {
        MainWindow w;
        QVERIFY(w.show_view("section"));
        w.tree()->select_pointer("/objects/1");
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* view = w.section_view();
        QTest::mouseClick(view, Qt::LeftButton, {}, QPoint(2, 2));  // empty paper
        QCOMPARE(view->selected_object(), -1);
        QCOMPARE(w.document()->undo_stack()->count(), 0);

        w.tree()->select_pointer("/objects/1");
        QTemporaryDir dir;
        const QString path = dir.filePath("section.svg");
        QString error;
        QVERIFY2(view->export_svg(path, &error), qPrintable(error));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray svg = file.readAll();
        QVERIFY(svg.startsWith("<svg"));
        QVERIFY(svg.contains("<polygon"));        // the cross-sections
        QVERIFY(svg.contains("stroke-opacity"));  // rays faded by weight
        QVERIFY(svg.contains("white light"));  // the lamp's, through glass that does not disperse
        QVERIFY(!view->export_svg(dir.filePath("missing/section.svg"), &error));
    }

    void the_wheel_zooms_about_the_cursor() {
        MainWindow w;
        QVERIFY(w.show_view("section"));
        w.tree()->select_pointer("/objects/1");
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* view = w.section_view();
        const lenslab::SectionExtent before = view->section().extent;
        const QPointF cursor = drawn_centre(*view, 1);
        const lenslab::DiagramView v = view->placement();
        const DiagramPoint under{v.z_min + (cursor.x() - v.left) / v.scale,
                                 v.y_max - (cursor.y() - v.top) / v.scale};
        QWheelEvent wheel(cursor, view->mapToGlobal(cursor), {}, {0, 120}, Qt::NoButton, {},
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(view, &wheel);
        const lenslab::SectionExtent after = view->section().extent;
        // One notch in: 0.85 of the width, the point under the cursor kept.
        QVERIFY(std::abs((after.a_max - after.a_min) - 0.85 * (before.a_max - before.a_min)) <
                1e-9);
        QVERIFY(std::abs((under.z - after.a_min) - 0.85 * (under.z - before.a_min)) < 1e-9);
        QVERIFY(std::abs((under.y - after.b_min) - 0.85 * (under.y - before.b_min)) < 1e-9);
        // The extent holds through an edit, and a new selection fits the view again.
        QString error;
        QVERIFY(w.document()->set_value(nlohmann::json::json_pointer("/objects/1/aperture_radius"),
                                        0.45, "aperture", &error));
        QCOMPARE(view->section().extent.a_min, after.a_min);
        w.tree()->select_pointer("/objects/0");
        w.tree()->select_pointer("/objects/1");
        QVERIFY(view->section().extent.a_max - view->section().extent.a_min >
                after.a_max - after.a_min);
    }

    void the_plane_can_be_chosen() {
        MainWindow w;
        QVERIFY(w.show_view("section"));
        w.tree()->select_pointer("/objects/0");  // the glass ball at (-1, 0.78, 0.2)
        auto* plane = w.findChild<QComboBox*>("section_plane");
        QVERIFY(plane);
        plane->setCurrentIndex(2);  // y-z
        auto* view = w.section_view();
        QCOMPARE(view->plane_choice(), lenslab::SectionPlaneChoice::YZ);
        const lenslab::SectionPlane& p = view->section().plane;
        QCOMPARE(p.normal().x, 1.0);
        QCOMPARE(p.origin.x, -1.0);  // through the selected ball
        // The ball is cut through its centre: a circle of its radius, 0.55.
        bool ball = false;
        for (const auto& o : view->section().objects) {
            if (o.object != 0) continue;
            ball = true;
            for (const DiagramPoint& q : o.curves.at(0).points) {
                const lenslab::Vec3 x = p.at(q);
                QVERIFY(std::abs(length(x - lenslab::Vec3{-1, 0.78, 0.2}) - 0.55) < 1e-8);
            }
        }
        QVERIFY(ball);
        QVERIFY(!view->section().rays.empty());  // the beam across it
    }

    void screenshot_of_the_section_view() {
        QTemporaryDir dir;
        const QString png = dir.filePath("section.png");
        QProcess gui;
        gui.start(LENSLAB_GUI_BINARY,
                  {"--screenshot", png, "--view", "section", "--select", "/objects/1"});
        QVERIFY(gui.waitForFinished(120000));
        QCOMPARE(gui.exitCode(), 0);
        QImage image(png);
        QVERIFY(!image.isNull());
        QVERIFY(image.width() >= 640 && image.height() >= 400);
        // The section's selected lens (outlined in orange) is on it: the 3-D view is not.
        int outline = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                outline +=
                    std::abs(c.red() - 255) < 6 && std::abs(c.green() - 140) < 12 && c.blue() < 40;
            }
        }
        QVERIFY2(outline > 30, qPrintable(QString::number(outline)));

        QProcess bad;
        bad.start(LENSLAB_GUI_BINARY, {"--screenshot", png, "--view", "side"});
        QVERIFY(bad.waitForFinished(60000));
        QCOMPARE(bad.exitCode(), 2);
        QVERIFY(bad.readAllStandardError().contains("--view must be 3d or section"));
    }
};

QTEST_MAIN(TestSectionView)
#include "test_section_view.moc"
