// Edit ▸ Tolerance lenses…: the sensitivity table and the Monte Carlo of the selected lens's
// system run in the background, the table and summary shown, the document unchanged.

#include <QLabel>
#include <QProgressBar>
#include <QSpinBox>
#include <QTableWidget>
#include <QtTest>

#include "bench_figure_view.h"
#include "main_window.h"
#include "scene_document.h"
#include "scene_tree.h"
#include "tolerance_dialog.h"

using lenslab::gui::MainWindow;
using lenslab::gui::ToleranceDialog;

namespace {

// The Tolerance dialog for the biconvex singlet of thick_lens_beam.json, opened in `w`.
ToleranceDialog* singlet_dialog(MainWindow& w) {
    if (!w.open_file(LENSLAB_SOURCE_DIR "/scenes/thick_lens_beam.json")) return nullptr;
    w.tree()->select_pointer("/objects/0");
    return w.tolerance_selected_lens();
}

}  // namespace

class TestToleranceDialog : public QObject {
    Q_OBJECT

private slots:
    // The singlet's two radii and its thickness, each tried at ± the error, then 12 made
    // lenses: the table has their three rows, the summary the Monte Carlo, the scene is as it
    // was.
    void a_run_shows_the_table_and_the_monte_carlo() {
        MainWindow w;
        ToleranceDialog* dialog = singlet_dialog(w);
        QVERIFY(dialog);
        const nlohmann::json original = w.document()->json();
        lenslab::gui::ToleranceChoices choices = dialog->choices();
        choices.optics.fields = {0.0};
        choices.optics.wavelengths = {587.5618};
        choices.trials = 12;
        dialog->set_choices(choices);
        QCOMPARE(dialog->findChild<QSpinBox*>("trials")->value(), 12);
        QSignalSpy finished(dialog, &ToleranceDialog::finished_run);
        QVERIFY2(dialog->start(), qPrintable(dialog->status()));
        QVERIFY(finished.wait(60000));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(dialog->status()));
        QTableWidget* table = dialog->findChild<QTableWidget*>("sensitivity");
        QVERIFY(table);
        QCOMPARE(table->rowCount(), 3);
        QVERIFY(table->item(0, 0)->text().startsWith("radius "));
        QVERIFY(table->item(2, 0)->text().startsWith("thickness "));
        QVERIFY2(dialog->status().contains("Monte Carlo of 12 lenses"),
                 qPrintable(dialog->status()));
        QCOMPARE(dialog->progress()->value(), 12);
        // The Monte Carlo's figure, as `lenslab tolerance --figure` draws it.
        QVERIFY(dialog->figure()->figure());
        QCOMPARE(QString::fromStdString(dialog->figure()->figure()->title),
                 QString("Monte Carlo of 12 made lenses"));
        QVERIFY(w.document()->json() == original);
    }

    // A decentre and a tilt alone: the singlet's four rows (x and y of each), the decentre's
    // two ends alike across the field's plane (x), the scene as it was.
    void decentre_and_tilt_rows() {
        MainWindow w;
        ToleranceDialog* dialog = singlet_dialog(w);
        QVERIFY(dialog);
        const nlohmann::json original = w.document()->json();
        lenslab::gui::ToleranceChoices choices = dialog->choices();
        choices.optics.fields = {0.0, 2.0};
        choices.optics.wavelengths = {587.5618};
        choices.radius = choices.thickness = choices.air_gap = 0;
        choices.decenter = 0.05;
        choices.tilt = 0.1;
        choices.trials = 4;
        dialog->set_choices(choices);
        QSignalSpy finished(dialog, &ToleranceDialog::finished_run);
        QVERIFY2(dialog->start(), qPrintable(dialog->status()));
        QVERIFY(finished.wait(60000));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(dialog->status()));
        QTableWidget* table = dialog->findChild<QTableWidget*>("sensitivity");
        QCOMPARE(table->rowCount(), 4);
        QVERIFY2(table->item(0, 0)->text().startsWith("decentre x "),
                 qPrintable(table->item(0, 0)->text()));
        QVERIFY(table->item(3, 0)->text().startsWith("tilt y "));
        QCOMPARE(table->item(0, 1)->text(), table->item(0, 2)->text());
        QVERIFY(w.document()->json() == original);
    }

    void no_error_to_try_is_said() {
        MainWindow w;
        ToleranceDialog* dialog = singlet_dialog(w);
        QVERIFY(dialog);
        lenslab::gui::ToleranceChoices choices = dialog->choices();
        choices.radius = choices.thickness = choices.air_gap = 0;
        dialog->set_choices(choices);
        QVERIFY(!dialog->start());
        QVERIFY2(dialog->status().contains("no tolerance to try"), qPrintable(dialog->status()));
    }
};

QTEST_MAIN(TestToleranceDialog)
#include "test_tolerance_dialog.moc"
