// The detector dock and the panels of flat objects, driven as a user would on the offscreen
// platform: select a detector, press Measure, see its irradiance map and totals; mark a new
// disc as a detector from its panel.

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalSpy>
#include <QSpinBox>
#include <QtTest>

#include "detector_dock.h"
#include "main_window.h"
#include "number_field.h"
#include "property_panel.h"
#include "scene_document.h"
#include "scene_tree.h"

using lenslab::gui::DetectorDock;
using lenslab::gui::MainWindow;
using lenslab::gui::NumberField;
using nlohmann::json;

class TestDetectorDock : public QObject {
    Q_OBJECT

private slots:
    void selecting_a_detector_and_measuring_shows_its_map() {
        MainWindow w;
        QString error;
        QVERIFY2(w.open_file(LENSLAB_SOURCE_DIR "/scenes/detector_focus.json", &error),
                 qPrintable(error));
        DetectorDock* dock = w.detector_dock();
        w.tree()->select_pointer("/objects/1");
        QCOMPARE(dock->shown_object(), 1);
        QVERIFY(dock->shown_measurement() == nullptr);
        QVERIFY(dock->summary_text().contains("Measure"));

        dock->photons_box()->setValue(20000);
        QSignalSpy measured(dock, &DetectorDock::measured);
        dock->findChild<QPushButton*>("detector_measure")->click();
        QVERIFY(measured.wait(60000));
        const lenslab::DetectorMeasurement* m = dock->shown_measurement();
        QVERIFY(m);
        QCOMPARE(m->name, std::string("focal plane"));
        // The beam's 1 W less the Fresnel losses at the lens's two faces (about 8%).
        QVERIFY2(m->total_power > 0.89 && m->total_power < 0.94,
                 qPrintable(QString::number(m->total_power)));
        QVERIFY(!dock->picture()->pixmap().isNull());
        QVERIFY(dock->picture()->pixmap().width() > 100);
        QVERIFY2(dock->summary_text().contains("total power"), qPrintable(dock->summary_text()));
        QVERIFY(dock->summary_text().contains("W/mm^2"));

        // Selecting something else keeps the detector; an edit makes the map stale.
        w.tree()->select_pointer("/objects/0");
        QCOMPARE(dock->shown_object(), 1);
        w.tree()->select_pointer("/objects/1");
        QVERIFY(w.panel()->findChild<NumberField*>("field:radius"));
        auto* radius = w.panel()->findChild<NumberField*>("field:radius");
        radius->setText(QString::number(0.5));
        emit radius->editingFinished();
        QCOMPARE(w.document()->json()["objects"][1]["radius"].get<double>(), 0.5);
        QVERIFY(dock->shown_measurement() == nullptr);
    }

    // A detector's figures (a line per band) scroll inside the dock instead of stretching it
    // past the window.
    void long_results_scroll() {
        MainWindow w;
        auto* summary = w.detector_dock()->findChild<QLabel*>("detector_summary");
        QVERIFY(summary);
        QStringList lines;
        for (int i = 0; i < 60; ++i) lines << QString("band %1: 0.123456 W").arg(i);
        summary->setText(lines.join('\n'));
        QVERIFY(qobject_cast<QScrollArea*>(summary->parentWidget()->parentWidget()));
        QVERIFY2(w.detector_dock()->minimumSizeHint().height() < 400,
                 qPrintable(QString::number(w.detector_dock()->minimumSizeHint().height())));
    }

    void a_new_disc_is_a_detector_and_its_flag_can_be_cleared() {
        MainWindow w;  // the default scene has no detector
        DetectorDock* dock = w.detector_dock();
        QCOMPARE(dock->shown_object(), -1);
        QVERIFY(!dock->findChild<QPushButton*>("detector_measure")->isEnabled());
        w.add_element("disc");
        const int index = int(w.document()->json()["objects"].size()) - 1;
        QCOMPARE(QString::fromStdString(
                     w.document()->json()["objects"][index]["type"].get<std::string>()),
                 QString("disc"));
        QCOMPARE(dock->shown_object(), index);
        QVERIFY(dock->findChild<QPushButton*>("detector_measure")->isEnabled());

        // The panel edits the detector's cells and turns the flag off.
        auto* cells = w.panel()->findChild<NumberField*>("field:detector/resolution");
        QVERIFY(cells);
        cells->setText(QString::number(32));
        emit cells->editingFinished();
        QCOMPARE(w.document()->json()["objects"][index]["detector"]["resolution"].get<int>(), 32);
        auto* flag = w.panel()->findChild<QComboBox*>("field:detector");
        QVERIFY(flag);
        flag->setCurrentText("no");
        emit flag->activated(flag->currentIndex());
        QVERIFY(!w.document()->json()["objects"][index].contains("detector"));
        QCOMPARE(dock->shown_object(), -1);
    }

    void detector_true_becomes_an_object_when_a_field_is_edited() {
        MainWindow w;
        json j = w.document()->json();
        j["objects"].push_back({{"type", "rectangle"},
                                {"center", {0, 1, 0}},
                                {"normal", {0, 0, 1}},
                                {"size", {1, 2}},
                                {"material", {{"color", 0.5}}},
                                {"detector", true}});
        QVERIFY(w.document()->apply(j, "add", nullptr));
        const int index = int(j["objects"].size()) - 1;
        w.tree()->select_pointer(QString("/objects/%1").arg(index));
        auto* side = w.panel()->findChild<QComboBox*>("field:detector/side");
        QVERIFY(side);
        side->setCurrentText("both");
        emit side->activated(side->currentIndex());
        QCOMPARE(w.document()->json()["objects"][index]["detector"], json({{"side", "both"}}));
        QVERIFY(w.panel()->findChild<NumberField*>("field:size/1"));
    }
};

QTEST_MAIN(TestDetectorDock)
#include "test_detector_dock.moc"
