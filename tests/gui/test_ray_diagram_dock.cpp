// The ray diagram dock follows the selection: a lens shows the diagram of the lenses on its
// axis with their figures, anything else shows why there is none, and an edit redraws it.

#include <QtTest>

#include "analysis/system/paraxial.h"
#include "main_window.h"
#include "ray_diagram_dock.h"
#include "scene_document.h"
#include "scene_tree.h"

using lenslab::gui::MainWindow;

class TestRayDiagramDock : public QObject {
    Q_OBJECT

private slots:
    void selecting_a_lens_draws_its_system() {
        MainWindow w;
        QString error;
        QVERIFY2(w.open_file(LENSLAB_SOURCE_DIR "/scenes/achromat_doublet.json", &error),
                 qPrintable(error));
        auto* dock = w.ray_diagram();
        QVERIFY(dock);
        QVERIFY(!dock->has_diagram());  // the camera is selected after opening

        w.tree()->select_pointer("/objects/1");  // the flint: the doublet is on its axis
        QVERIFY2(dock->has_diagram(), qPrintable(dock->message()));
        // Two cemented lenses: two outlines, and the figures of the whole doublet
        // (Thorlabs AC254-100-A, f = 100.1 mm).
        const auto& diagram = *dock->view()->diagram();
        int outlines = 0;
        for (const auto& p : diagram.paths) outlines += p.closed ? 1 : 0;
        QCOMPARE(outlines, 2);
        QVERIFY2(dock->message().contains("EFL 100.1"), qPrintable(dock->message()));

        // The dock paints something other than white where the lenses are.
        dock->resize(800, 360);
        const QImage image = dock->view()->grab().toImage();
        int coloured = 0;
        for (int y = 0; y < image.height(); y += 2) {
            for (int x = 0; x < image.width(); x += 2)
                coloured += image.pixel(x, y) != qRgb(255, 255, 255);
        }
        QVERIFY(coloured > 200);

        w.tree()->select_pointer("/objects/2");  // the screen, a triangle
        QVERIFY(!dock->has_diagram());
        QVERIFY(dock->message().contains("Select a lens"));
    }

    void an_edit_redraws_the_diagram() {
        MainWindow w;
        QVERIFY(w.open_file(LENSLAB_SOURCE_DIR "/scenes/thick_lens_beam.json"));
        w.tree()->select_pointer("/objects/0");
        auto* dock = w.ray_diagram();
        QVERIFY(dock->has_diagram());
        QVERIFY2(dock->message().contains("EFL 50.847"), qPrintable(dock->message()));
        // A thicker lens: EFL from the thick-lens equation (Hecht eq. 6.2) with d = 8.
        QString error;
        QVERIFY2(w.document()->set_value(nlohmann::json::json_pointer("/objects/0/thickness"), 8.0,
                                         "thickness", &error),
                 qPrintable(error));
        const double n = 1.5, r = 50.0, d = 8.0;
        const double f = 1.0 / ((n - 1) * (2.0 / r - (n - 1) * d / (n * r * r)));
        QVERIFY2(dock->message().contains(QString("EFL %1").arg(f, 0, 'f', 3)),
                 qPrintable(dock->message()));
    }
};

QTEST_MAIN(TestRayDiagramDock)
#include "test_ray_diagram_dock.moc"
