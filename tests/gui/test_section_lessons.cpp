// The classroom walkthroughs of docs/lessons.md, done in the Section tab as the lesson says,
// each against the number a textbook gives: a prism's minimum deviation read with the
// protractor (Hecht, Optics, 5.5.1: 37.18° for A = 60°, n = 1.5), a lens's back focal
// distance found by dragging a screen (thick-lens equation: 49.15 mm), total internal
// reflection in a light pipe (beyond asin(1/1.5) = 41.81°). With LENSLAB_LESSON_SCREENSHOTS
// set to a folder, each writes the window's picture there (docs/images/lesson_*.png).

#include <QFile>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>
#include <cmath>
#include <numbers>

#include "analysis/section/section_ray_report.h"
#include "analysis/trace/ray_tree.h"
#include "main_window.h"
#include "scene_document.h"
#include "scene_tree.h"
#include "section_test_support.h"
#include "section_widget.h"

using lenslab::SectionRayPath;
using lenslab::Vec3;
using lenslab::gui::MainWindow;
using namespace lenslab::gui::testing;

namespace {

void save_lesson_picture(MainWindow& w, const char* name) {
    const QByteArray folder = qgetenv("LENSLAB_LESSON_SCREENSHOTS");
    if (folder.isEmpty()) return;
    QTest::qWait(50);  // the read-out's new height laid out
    QVERIFY(w.grab().save(QString::fromLocal8Bit(folder) + "/" + name));
}

// The spread (max - min) of where the beam light's strong rays end along the plane's v: the
// size of the spot on the screen. The beam starts at z = -40 within 3 mm of the axis.
double spot_size(const lenslab::gui::SectionWidget& view) {
    const auto& plane = view.section().plane;
    double lo = INFINITY, hi = -INFINITY;
    for (const SectionRayPath& r : view.section().rays) {
        const lenslab::DiagramPoint start = plane.of(r.points[0]);
        if (r.weight < 0.5 || std::abs(r.points[0].z + 40) > 1e-9 || std::abs(start.y) > 3.001)
            continue;
        const double y = plane.of(r.points.back()).y;
        lo = std::min(lo, y), hi = std::max(hi, y);
    }
    return hi - lo;
}

}  // namespace

class TestSectionLessons : public QObject {
    Q_OBJECT

private slots:
    void the_protractor_reads_the_prisms_deviation_as_the_tracer() {
        MainWindow w;
        open_prism_from_above(w);
        auto* view = w.section_view();
        w.findChild<QToolButton*>("section_tool_protractor")->click();
        QCOMPARE(view->tool(), lenslab::gui::SectionTool::Protractor);
        const SectionRayPath* ray = beam_middle_ray(*view);
        QVERIFY(ray && ray->points.size() >= 4);
        const size_t n = ray->points.size();
        QTest::mouseClick(view, Qt::LeftButton, {}, segment_middle(*view, *ray, 0));
        QTest::mouseClick(view, Qt::LeftButton, {}, segment_middle(*view, *ray, n - 2));
        const std::optional<double> reading = view->protractor_reading();
        QVERIFY(reading);
        // The same start ray through trace_ray_tree (what `lenslab trace` prints), along its
        // refracted branches to the screen.
        lenslab::RayTreeOptions options;
        const lenslab::RayTree tree =
            trace_ray_tree(w.document()->scene(),
                           {ray->points[0], normalize(ray->points[1] - ray->points[0])}, options);
        const lenslab::RayTreeNode* node = &tree.root;
        while (true) {
            const lenslab::RayTreeNode* next = nullptr;
            for (const auto& c : node->children) {
                if (c.event == lenslab::Event::Refract) next = &c;
            }
            if (!next) break;
            node = next;
        }
        const double traced = lenslab::angle_between_deg(tree.root.direction, node->direction);
        QVERIFY2(std::abs(*reading - traced) < 0.1,
                 qPrintable(QString("%1 vs %2").arg(*reading).arg(traced)));
        QVERIFY(std::abs(traced - 37.18) < 0.02);  // Hecht's minimum deviation, the scene's
        save_lesson_picture(w, "lesson_prism.png");
        // The exported drawing carries the protractor: its arms, arc and reading.
        QTemporaryDir dir;
        QString error;
        QVERIFY2(view->export_svg(dir.filePath("prism.svg"), &error), qPrintable(error));
        QFile svg(dir.filePath("prism.svg"));
        QVERIFY(svg.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(svg.readAll());
        QVERIFY2(text.contains(QString("%1°").arg(*reading, 0, 'f', 2)),
                 qPrintable(text.right(600)));
        QVERIFY(text.contains("#7828a0"));  // the measuring ink

        // Step 4: with Move, turn the prism (Shift and drag): the protractor's arms follow the
        // beam's first and last legs, and the deviation grows from its minimum.
        w.findChild<QToolButton*>("section_tool_move")->click();
        const QPoint grip = drawn_middle(*view, 0) + QPoint(0, -4);
        QTest::mousePress(view, Qt::LeftButton, Qt::ShiftModifier, grip);
        for (int i = 1; i <= 4; ++i) {
            const QPointF at(grip + QPoint(2 * i, 0));
            QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton,
                             Qt::LeftButton, Qt::ShiftModifier);
            QApplication::sendEvent(view, &move);
        }
        QTest::mouseRelease(view, Qt::LeftButton, Qt::ShiftModifier, grip + QPoint(8, 0));
        QCOMPARE(w.document()->undo_stack()->count(), 1);
        const std::optional<double> turned = view->protractor_reading();
        QVERIFY(turned);
        QVERIFY2(*turned > *reading + 0.01,
                 qPrintable(QString("%1 after %2").arg(*turned).arg(*reading)));
        const QString shown = w.findChild<QPlainTextEdit*>("section_readout")->toPlainText();
        QCOMPARE(shown, QString("Protractor: %1°").arg(*turned, 0, 'f', 2));
    }

    void a_screen_dragged_to_the_smallest_spot_finds_the_back_focus() {
        MainWindow w;
        open_section(w, "focal_length_bench.json");
        auto* view = w.section_view();
        w.tree()->select_pointer("/objects/0");  // the lens: the plane through its axis
        w.findChild<QToolButton*>("section_fit_all")->click();
        const double scale = view->placement().scale;  // pixels per mm
        QVERIFY(scale > 3);
        // Drag the screen's edge towards the lens a pixel at a time, watching the spot.
        const QPoint grip = view->to_widget({80, 15}).toPoint();
        QTest::mousePress(view, Qt::LeftButton, {}, grip);
        double smallest = INFINITY, best_shift = 0;
        const int steps = int(45 * scale);  // to z = 35
        for (int i = 1; i <= steps; ++i) {
            QTest::mouseMove(view, grip - QPoint(i, 0));
            const double spot = spot_size(*view);
            if (spot < smallest) smallest = spot, best_shift = i / scale;
        }
        QTest::mouseRelease(view, Qt::LeftButton, {}, grip - QPoint(steps, 0));
        const double screen_z = 80 - best_shift;
        // The back vertex is at z = 2.5; the paraxial focus 49.15 mm behind it. Spherical
        // aberration puts the smallest spot of this 6 mm beam a little nearer the lens.
        QVERIFY2(std::abs(screen_z - (2.5 + 49.15)) < 0.5,
                 qPrintable(QString("smallest spot %1 mm at z = %2").arg(smallest).arg(screen_z)));
        QVERIFY(smallest < 0.1);

        // Put it there and measure from the back vertex with the ruler.
        QString error;
        QVERIFY(w.document()->set_value(nlohmann::json::json_pointer("/objects/1/center/2"),
                                        screen_z, "screen", &error));
        w.findChild<QToolButton*>("section_tool_ruler")->click();
        const QPoint a = view->to_widget({2.5, -14}).toPoint();
        const QPoint b = view->to_widget({screen_z, -14}).toPoint();
        QTest::mousePress(view, Qt::LeftButton, {}, a);
        QTest::mouseMove(view, (a + b) / 2);
        QTest::mouseMove(view, b);
        QTest::mouseRelease(view, Qt::LeftButton, {}, b);
        const QString ruler = w.findChild<QPlainTextEdit*>("section_readout")->toPlainText();
        QVERIFY2(ruler.startsWith("Ruler: 4"), qPrintable(ruler));
        save_lesson_picture(w, "lesson_focal_length.png");
    }

    void a_light_pipe_reflects_totally_beyond_the_critical_angle() {
        MainWindow w;
        open_section(w, "light_pipe.json");
        auto* view = w.section_view();
        w.findChild<QComboBox*>("section_plane")->setCurrentIndex(1);  // x-y: the laser's
        const SectionRayPath* ray = nullptr;
        for (const SectionRayPath& r : view->section().rays) {
            if (r.weight > 0.5 && (!ray || r.points.size() > ray->points.size())) ray = &r;
        }
        QVERIFY(ray);
        QTest::mouseClick(view, Qt::LeftButton, {}, segment_middle(*view, *ray, 0));
        QVERIFY(view->inspected_ray() >= 0);
        const lenslab::SectionRayReport report = section_ray_report(
            w.document()->scene(), view->section().rays[size_t(view->inspected_ray())]);
        const double critical = std::asin(1 / 1.5) * 180 / std::numbers::pi;  // 41.81°
        int total = 0;
        for (const lenslab::SectionRayStep& s : report.steps) {
            if (s.event != lenslab::Event::Tir) continue;
            ++total;
            QVERIFY(s.incidence_deg > critical);
            QVERIFY(std::abs(s.incidence_deg - 70.53) < 0.01);  // 90° - asin(sin 30° / 1.5)
            QVERIFY(std::abs(s.leaving_deg - s.incidence_deg) < 1e-9);
        }
        QCOMPARE(total, 5);
        QVERIFY(view->inspected_text().contains("totally reflected, incidence 70.53°"));
        save_lesson_picture(w, "lesson_light_pipe.png");
    }
};

QTEST_MAIN(TestSectionLessons)
#include "test_section_lessons.moc"
