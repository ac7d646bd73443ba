// The section view as a teaching bench (issue 41): the smoke tank's green lasers drawn to the
// screen across the tab, the achromat's focus in view after Fit all, a clicked ray's angles,
// panning, turning an object with Shift, the ruler, the ray count and the PNG export. The
// classroom walkthroughs (test_section_lessons.cpp) use the protractor.

#include <QComboBox>
#include <QPlainTextEdit>
#include <QProcess>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

#include "main_window.h"
#include "scene_document.h"
#include "scene_tree.h"
#include "section_test_support.h"
#include "section_widget.h"

using lenslab::DiagramPoint;
using lenslab::SectionRayPath;
using lenslab::Vec3;
using lenslab::gui::MainWindow;
using lenslab::gui::SectionWidget;
using namespace lenslab::gui::testing;

namespace {

// The first and last columns of `area` holding a green pixel (a 532 nm ray drawn on white);
// (width, -1) for none.
std::pair<int, int> green_columns(const QImage& image, const QRect& area) {
    int first = image.width(), last = -1;
    for (int x = area.left(); x <= area.right(); ++x) {
        for (int y = area.top(); y <= area.bottom(); ++y) {
            const QColor c = image.pixelColor(x, y);
            if (c.green() > 100 && c.green() > 2 * c.red() && c.green() > 2 * c.blue()) {
                first = std::min(first, x), last = std::max(last, x);
                break;
            }
        }
    }
    return {first, last};
}

}  // namespace

class TestSectionBench : public QObject {
    Q_OBJECT

private slots:
    void the_smoke_tanks_lasers_reach_the_screen_in_green() {
        MainWindow w;
        open_section(w, "smoke_tank.json");
        auto* view = w.section_view();
        // Every ray at the lasers' 532 nm, drawn green.
        QVERIFY(view->section().rays.size() >= 10);
        for (const SectionRayPath& r : view->section().rays)
            QVERIFY(std::abs(r.wavelength_nm - 532) < 0.05);
        // On the picture: green pixels in columns across most of the view's width.
        const QImage image = view->grab().toImage();
        const auto [first, last] = green_columns(image, image.rect());
        QVERIFY2(last - first > 0.75 * image.width(),
                 qPrintable(QString("%1-%2 of %3").arg(first).arg(last).arg(image.width())));
        // The beams end on the screen (objects[1]), which is in view.
        int on_screen = 0;
        for (const SectionRayPath& r : view->section().rays) {
            if (!r.hits.empty() && r.hits.back().object == 1 && r.weight > 0.5) {
                const QPointF end = view->to_widget(view->section().plane.of(r.points.back()));
                on_screen += view->rect().contains(end.toPoint());
            }
        }
        QVERIFY2(on_screen >= 10, qPrintable(QString::number(on_screen)));
    }

    // The same through `lenslab-gui --screenshot FILE --view section`, as the issue asks: the
    // window's grab shows green across most of the section's width.
    void the_smoke_tanks_screenshot_shows_the_green_beams() {
        QTemporaryDir dir;
        const QString png = dir.filePath("smoke_tank.png");
        QProcess gui;
        gui.start(LENSLAB_GUI_BINARY, {"--screenshot", png, "--view", "section",
                                       LENSLAB_SOURCE_DIR "/scenes/smoke_tank.json"});
        QVERIFY(gui.waitForFinished(120000));
        QCOMPARE(gui.exitCode(), 0);
        const QImage image(png);
        QCOMPARE(image.size(), QSize(1280, 800));
        // The section view lies in the middle column (the docks either side show no green).
        MainWindow w;
        open_section(w, "smoke_tank.json");
        const QRect view(w.section_view()->mapTo(&w, QPoint(0, 0)), w.section_view()->size());
        const auto [first, last] = green_columns(image, view);
        QVERIFY2(last - first > 0.75 * view.width(),
                 qPrintable(QString("%1-%2 of %3").arg(first).arg(last).arg(view.width())));
    }

    void fit_all_shows_the_achromats_focus() {
        MainWindow w;
        open_section(w, "achromat_doublet.json");
        w.tree()->select_pointer("/objects/0");
        auto* view = w.section_view();
        w.findChild<QToolButton*>("section_fit_selection")->click();
        const lenslab::SectionExtent tight = view->section().extent;
        w.findChild<QToolButton*>("section_fit_all")->click();
        const lenslab::SectionExtent all = view->section().extent;
        QVERIFY(all.a_max - all.a_min > 2 * (tight.a_max - tight.a_min));
        // The focus: where the beam's two outermost rays cross after the lens, in view.
        const auto& plane = view->section().plane;
        const SectionRayPath *low = nullptr, *high = nullptr;
        for (const SectionRayPath& r : view->section().rays) {
            if (r.weight < 0.5 || r.points.size() < 4 || r.wavelength_nm != lenslab::kLineD)
                continue;
            const double y = plane.of(r.points[0]).y;
            if (!low || y < plane.of(low->points[0]).y) low = &r;
            if (!high || y > plane.of(high->points[0]).y) high = &r;
        }
        QVERIFY(low && high && low != high);
        const auto last_arm = [&](const SectionRayPath& r) {
            const size_t n = r.points.size();
            return lenslab::gui::SectionArm{plane.of(r.points[n - 2]), plane.of(r.points[n - 1])};
        };
        const auto focus = lenslab::gui::arms_crossing(last_arm(*low), last_arm(*high));
        QVERIFY(focus);
        // The back focus of a 100 mm doublet whose front lies at z = 0.
        QVERIFY2(focus->z > 90, qPrintable(QString::number(focus->z)));
        QVERIFY(view->rect().contains(view->to_widget(*focus).toPoint()));
    }

    void a_clicked_ray_reports_its_angles_and_paper_pans() {
        MainWindow w;
        open_prism_from_above(w);
        auto* view = w.section_view();
        const SectionRayPath* ray = beam_middle_ray(*view);
        QVERIFY(ray);
        QTest::mouseClick(view, Qt::LeftButton, {}, segment_middle(*view, *ray, 0));
        QVERIFY(view->inspected_ray() >= 0);
        QVERIFY2(view->inspected_text().contains("1. prism: refracted, incidence 48.59°"),
                 qPrintable(view->inspected_text()));
        QCOMPARE(view->selected_object(), 0);  // the selection stays
        auto* readout = w.findChild<QPlainTextEdit*>("section_readout");
        QCOMPARE(readout->toPlainText(), view->inspected_text());

        // A drag on empty paper pans by as much; nothing is edited.
        const lenslab::SectionExtent before = view->section().extent;
        const double scale = view->placement().scale;
        const QPoint from(8, view->height() / 2 + 40), to = from + QPoint(50, 0);
        QTest::mousePress(view, Qt::LeftButton, {}, from);
        for (int i = 1; i <= 5; ++i) QTest::mouseMove(view, from + (to - from) * i / 5);
        QTest::mouseRelease(view, Qt::LeftButton, {}, to);
        const lenslab::SectionExtent after = view->section().extent;
        QVERIFY(std::abs((before.a_min - after.a_min) - 50 / scale) < 1e-6);
        QCOMPARE(w.document()->undo_stack()->count(), 0);
    }

    void shift_drag_turns_the_prism_by_one_edit() {
        MainWindow w;
        open_prism_from_above(w);
        auto* view = w.section_view();
        const nlohmann::json before = w.document()->json();
        const QPoint grip = drawn_middle(*view, 0) + QPoint(0, -4);  // inside the prism
        QTest::mousePress(view, Qt::LeftButton, Qt::ShiftModifier, grip);
        for (int i = 1; i <= 6; ++i) {
            QMouseEvent move(QEvent::MouseMove, QPointF(grip + QPoint(3 * i, 0)),
                             view->mapToGlobal(QPointF(grip + QPoint(3 * i, 0))), Qt::NoButton,
                             Qt::LeftButton, Qt::ShiftModifier);
            QApplication::sendEvent(view, &move);
        }
        QTest::mouseRelease(view, Qt::LeftButton, Qt::ShiftModifier, grip + QPoint(18, 0));
        const nlohmann::json& prism = w.document()->json()["objects"][0];
        QVERIFY(prism["facing"] != before["objects"][0]["facing"]);
        QVERIFY(std::abs(prism["axis"][1].get<double>() - 1.0) < 1e-12);  // still upright
        QCOMPARE(w.document()->undo_stack()->count(), 1);
        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->json(), before);
    }

    void the_ruler_rays_and_png_export() {
        MainWindow w;
        open_prism_from_above(w);
        auto* view = w.section_view();
        w.findChild<QToolButton*>("section_tool_ruler")->click();
        const QPoint a = view->to_widget({0, 0}).toPoint();
        const QPoint b = a + QPoint(int(std::lround(view->placement().scale)), 0);  // 1 unit
        QTest::mousePress(view, Qt::LeftButton, {}, a);
        QTest::mouseMove(view, a + (b - a) / 2);
        QTest::mouseMove(view, b);
        QTest::mouseRelease(view, Qt::LeftButton, {}, b);
        auto* readout = w.findChild<QPlainTextEdit*>("section_readout");
        // One unit to the nearest pixel.
        const double measured = readout->toPlainText().section(' ', 1, 1).toDouble();
        QVERIFY2(std::abs(measured - 1) < 1 / view->placement().scale,
                 qPrintable(readout->toPlainText()));

        auto* rays = w.findChild<QSpinBox*>("section_rays");
        rays->setValue(40);
        QCOMPARE(view->rays(), 40);
        int strong = 0;
        for (const SectionRayPath& r : view->section().rays) strong += r.weight > 0.5;
        QVERIFY2(strong >= 40, qPrintable(QString::number(strong)));

        QTemporaryDir dir;
        QString error;
        QVERIFY2(view->export_png(dir.filePath("section.png"), &error), qPrintable(error));
        const QImage image(dir.filePath("section.png"));
        QCOMPARE(image.size(), view->size());
        QVERIFY(!view->export_png(dir.filePath("missing/section.png"), &error));
        QVERIFY(error.contains("missing/section.png"));
    }

    // At the default window's size every control of the section's tool bar shows; none is
    // folded into the bar's extension menu (Export... was, in the last trial).
    void the_whole_tool_bar_shows_at_the_default_size() {
        MainWindow w;
        open_section(w, "prism.json");
        auto* bar = w.findChild<QToolBar*>("section_tool_bar");
        QVERIFY(bar);
        QString widths;
        for (QWidget* child : bar->findChildren<QWidget*>(Qt::FindDirectChildrenOnly)) {
            if (child->objectName().startsWith("section_")) {
                widths += QString(" %1 %2").arg(child->objectName()).arg(child->width());
            }
        }
        widths += QString("; bar %1").arg(bar->width());
        for (const char* name : {"section_plane", "section_rays", "section_fit_all",
                                 "section_fit_selection", "section_tool_move", "section_tool_ruler",
                                 "section_tool_protractor", "section_export"}) {
            auto* control = bar->findChild<QWidget*>(name);
            QVERIFY2(control, name);
            QVERIFY2(control->isVisible(), qPrintable(name + widths));
        }
    }
};

QTEST_MAIN(TestSectionBench)
#include "test_section_bench.moc"
