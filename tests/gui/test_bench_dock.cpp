// The bench dock's figures for the selected lens: the spot tab shows the library's spot
// diagrams (the numbers of `lenslab analyze --spots` for the same settings), and the other
// tabs draw their figures; the PSF and wavefront tabs compute theirs only while shown.

#include <QAbstractScrollArea>
#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QFileInfo>
#include <QLineEdit>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>
#include <cmath>

#include "analysis/aberrations/spot_diagrams.h"
#include "analysis/report/lens_report.h"
#include "bench_figure_view.h"
#include "main_window.h"
#include "map_image_view.h"
#include "optics/glass.h"
#include "ray_diagram_dock.h"
#include "scene_document.h"
#include "scene_tree.h"

using lenslab::gui::MainWindow;

namespace {

// The scene object made from entry `source` of the file.
int object_from(const lenslab::Scene& scene, int source) {
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        if (scene.objects[i].source == source) return i;
    }
    return -1;
}

int painted_pixels(QWidget* widget) {
    const QImage image = widget->grab().toImage();
    int coloured = 0;
    for (int y = 0; y < image.height(); y += 2) {
        for (int x = 0; x < image.width(); x += 2)
            coloured += image.pixel(x, y) != qRgb(255, 255, 255);
    }
    return coloured;
}

}  // namespace

class TestBenchDock : public QObject {
    Q_OBJECT

private slots:
    void the_spot_tab_shows_the_librarys_numbers() {
        MainWindow w;
        QString error;
        QVERIFY2(w.open_file(LENSLAB_SOURCE_DIR "/scenes/achromat_doublet.json", &error),
                 qPrintable(error));
        auto* dock = w.ray_diagram();
        w.tree()->select_pointer("/objects/1");
        dock->tabs()->setCurrentIndex(1);  // Spots: computed after a pause
        QTRY_VERIFY(dock->bench().spots.has_value());
        QVERIFY2(dock->bench().errors.empty(), qPrintable(dock->spot_numbers()));

        // The library's spot diagrams for the same lens and settings.
        const lenslab::Scene& scene = w.document()->scene();
        const lenslab::OpticalSystem system =
            lenslab::build_optical_system(scene, object_from(scene, 1));
        lenslab::LensReportOptions options;
        options.wavelengths = {lenslab::kLineF, lenslab::kLineD, lenslab::kLineC};
        options.wavelength_nm = lenslab::kLineD;
        options.first_order.fields = {0.0, 5.0};
        options.spot_rings = dock->settings().rings;
        const lenslab::LensReport report = lenslab::analyze_lens_system(system, options);
        lenslab::SpotOptions spot;
        spot.fields = {0.0, 5.0};
        spot.wavelengths = report.wavelengths;
        spot.rings = dock->settings().rings;
        const lenslab::SpotDiagrams expected =
            lenslab::spot_diagrams(system, report.first_order, spot);

        QCOMPARE(dock->bench().spots->fields.size(), expected.fields.size());
        const QString numbers = dock->spot_numbers();
        const auto shown = [&numbers](double v) {
            return numbers.contains(QString::number(v, 'g', 4));
        };
        for (const lenslab::FieldSpots& field : expected.fields) {
            QVERIFY2(shown(field.polychromatic.rms_radius), qPrintable(numbers));
            QVERIFY2(shown(field.airy_radius), qPrintable(numbers));
            QCOMPARE(field.spots.size(), std::size_t(3));
            for (const lenslab::WavelengthSpot& s : field.spots) {
                QVERIFY2(shown(s.spot.rms_radius), qPrintable(numbers));
                QVERIFY2(shown(s.spot.geometric_radius), qPrintable(numbers));
            }
        }
        dock->resize(900, 420);
        QVERIFY(painted_pixels(dock->spot_view()) > 200);
        // The picture of docs/editor.md, when asked for.
        const QString screenshot = qEnvironmentVariable("LENSLAB_BENCH_SCREENSHOT");
        if (!screenshot.isEmpty()) QVERIFY(dock->grab().save(screenshot));
        QVERIFY(dock->bench().fans && dock->bench().curves && dock->bench().diffraction);

        // A double-click opens the figure in a window of its own, at the command line's size
        // (its text at full size: the dock showed it about 5 pixels high); it exports as the
        // command line writes it.
        QTest::mouseDClick(dock->spot_view(), Qt::LeftButton);
        auto* window = dock->spot_view()->findChild<QWidget*>("bench_figure_window");
        QVERIFY(window);
        QVERIFY(window->isVisible());
        QVERIFY2(window->width() >= 600, qPrintable(QString::number(window->width())));
        auto* big = window->findChild<lenslab::gui::BenchFigureView*>();
        QVERIFY(big && big->figure().has_value());
        QCOMPARE(big->figure()->title, dock->spot_view()->figure()->title);
        window->close();
        QTemporaryDir dir;
        QVERIFY2(dock->spot_view()->export_to(dir.filePath("spots.svg"), &error),
                 qPrintable(error));
        QVERIFY2(dock->spot_view()->export_to(dir.filePath("spots.png"), &error),
                 qPrintable(error));
        QFile svg(dir.filePath("spots.svg"));
        QVERIFY(svg.open(QIODevice::ReadOnly));
        QVERIFY(svg.readAll().contains("<svg"));
        QVERIFY(QFileInfo(dir.filePath("spots.png")).size() > 1000);
        QVERIFY(!dock->spot_view()->export_to(dir.filePath("missing/spots.png"), &error));
        QVERIFY2(error.contains("missing"), qPrintable(error));
    }

    // The trial's finding: at the default window size the dock drew the spot diagrams at a
    // fifth of their size, text about 5 pixels high. Now each figure is drawn at least at
    // BenchFigureView::kReadableZoom (the dock scrolls it), Ctrl+wheel zooms it, and a larger
    // dock draws it larger.
    void bench_figures_read_at_the_default_dock_size() {
        using lenslab::gui::BenchFigureView;
        MainWindow w;
        QVERIFY(w.open_file(LENSLAB_SOURCE_DIR "/scenes/achromat_doublet.json"));
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* dock = w.ray_diagram();
        w.tree()->select_pointer("/objects/1");
        for (const int tab : {1, 2, 3, 4}) {  // Spots, Fans, Field curves, MTF
            dock->tabs()->setCurrentIndex(tab);
            QTRY_VERIFY(dock->bench().spots && dock->bench().fans && dock->bench().curves &&
                        dock->bench().diffraction);
        }
        dock->tabs()->setCurrentIndex(1);
        BenchFigureView* spots = dock->spot_view();
        QTRY_VERIFY(spots->isVisible() && spots->figure().has_value());
        // The first figure tab shown grew the dock to 45% of the window.
        QVERIFY2(dock->height() >= w.height() * 45 / 100 - 2,
                 qPrintable(QString("%1 of %2").arg(dock->height()).arg(w.height())));
        if (qEnvironmentVariableIsSet("LENSLAB_BENCH_WINDOW")) {
            QVERIFY(w.grab().save(qEnvironmentVariable("LENSLAB_BENCH_WINDOW")));
        }
        const auto* area = qobject_cast<QAbstractScrollArea*>(
            spots->parentWidget() ? spots->parentWidget()->parentWidget() : nullptr);
        QVERIFY(area);
        // The dock shows part of the figure (it is taller than the dock) at a readable zoom.
        QVERIFY2(spots->drawn_zoom() >= BenchFigureView::kReadableZoom - 1e-9,
                 qPrintable(QString::number(spots->drawn_zoom())));
        QVERIFY2(
            area->viewport()->height() < spots->height(),
            qPrintable(QString("%1 < %2").arg(area->viewport()->height()).arg(spots->height())));

        // Ctrl+wheel: one notch in zooms by 1.25; out again, back.
        const double before = spots->drawn_zoom();
        const QPointF at(10, 10);
        QWheelEvent in(at, spots->mapToGlobal(at), {}, {0, 120}, Qt::NoButton, Qt::ControlModifier,
                       Qt::NoScrollPhase, false);
        QApplication::sendEvent(spots, &in);
        QTRY_VERIFY2(std::abs(spots->drawn_zoom() - 1.25 * before) < 0.01,
                     qPrintable(QString::number(spots->drawn_zoom())));
        QWheelEvent out(at, spots->mapToGlobal(at), {}, {0, -120}, Qt::NoButton,
                        Qt::ControlModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(spots, &out);
        QTRY_VERIFY2(std::abs(spots->drawn_zoom() - before) < 0.01,
                     qPrintable(QString::number(spots->drawn_zoom())));

        // Every figure tab at a readable zoom.
        for (BenchFigureView* view : dock->findChildren<BenchFigureView*>()) {
            if (!view->figure()) continue;
            QVERIFY2(view->least_zoom() >= BenchFigureView::kReadableZoom,
                     qPrintable(QString::fromStdString(view->figure()->title)));
        }
    }

    // The PSF and wavefront tabs: computed only while shown (they cost the most), drawn as the
    // command line's --psf-png and --opd-png draw them.
    void the_psf_and_wavefront_tabs_draw_only_when_shown() {
        MainWindow w;
        QVERIFY(w.open_file(LENSLAB_SOURCE_DIR "/scenes/achromat_doublet.json"));
        w.tree()->select_pointer("/objects/1");
        auto* dock = w.ray_diagram();
        dock->tabs()->setCurrentWidget(dock->psf_view());
        dock->update_bench();
        QCOMPARE(dock->bench().psfs.size(), std::size_t(2));  // fields 0 and 5
        QVERIFY(dock->bench().psfs[0].error.empty());
        QVERIFY(dock->bench().psfs[0].psf.strehl > 0);
        QVERIFY(!dock->bench().wavefronts.has_value());
        QVERIFY(!dock->psf_view()->image().isNull());
        dock->tabs()->setCurrentWidget(dock->wavefront_view());
        dock->update_bench();
        QVERIFY(dock->bench().wavefronts.has_value());
        QCOMPARE(dock->bench().wavefronts->figures.size(), std::size_t(2));
        QVERIFY(dock->bench().psfs.empty());
        QVERIFY(!dock->wavefront_view()->image().isNull());
        QVERIFY(dock->psf_view()->image().isNull());
    }

    void settings_and_edits_recompute_the_figures() {
        MainWindow w;
        QVERIFY(w.open_file(LENSLAB_SOURCE_DIR "/scenes/thick_lens_beam.json"));
        w.tree()->select_pointer("/objects/0");
        auto* dock = w.ray_diagram();
        dock->tabs()->setCurrentIndex(2);
        dock->fields_edit()->setText("0");
        dock->wavelengths_edit()->setText("587.5618");
        dock->update_bench();
        QVERIFY(dock->bench().spots.has_value());
        QCOMPARE(dock->bench().spots->fields.size(), std::size_t(1));
        QCOMPARE(dock->bench().spots->wavelengths.size(), std::size_t(1));
        const double before = dock->bench().spots->fields[0].polychromatic.rms_radius;

        QString error;
        QVERIFY2(w.document()->set_value(nlohmann::json::json_pointer("/objects/0/thickness"), 8.0,
                                         "thickness", &error),
                 qPrintable(error));
        QTRY_VERIFY(dock->bench().spots.has_value() &&
                    dock->bench().spots->fields[0].polychromatic.rms_radius != before);

        dock->fields_edit()->setText("0, x");
        dock->update_bench();
        QVERIFY(!dock->bench().spots.has_value());
        QVERIFY2(dock->spot_numbers().contains("Fields"), qPrintable(dock->spot_numbers()));
    }

    // The Aim box: rays aimed at the paraxial entrance pupil, as --ray-aiming paraxial, move
    // the off-axis spot of the achromat against rays aimed through the real stop.
    void ray_aiming_is_chosen_in_the_dock() {
        MainWindow w;
        QVERIFY(w.open_file(LENSLAB_SOURCE_DIR "/scenes/achromat_doublet.json"));
        w.tree()->select_pointer("/objects/1");
        auto* dock = w.ray_diagram();
        dock->tabs()->setCurrentIndex(1);
        dock->fields_edit()->setText("10");
        dock->update_bench();
        QVERIFY(dock->bench().spots.has_value());
        QCOMPARE(dock->settings().ray_aiming, lenslab::RayAiming::Real);
        const double real = dock->bench().spots->fields[0].polychromatic.rms_radius;
        auto* aim = dock->findChild<QComboBox*>("bench_ray_aiming");
        QVERIFY(aim);
        aim->setCurrentIndex(aim->findText("paraxial"));
        dock->update_bench();
        QCOMPARE(dock->settings().ray_aiming, lenslab::RayAiming::Paraxial);
        QVERIFY(dock->bench().spots.has_value());
        QVERIFY(dock->bench().spots->fields[0].polychromatic.rms_radius != real);
    }
};

QTEST_MAIN(TestBenchDock)
#include "test_bench_dock.moc"
