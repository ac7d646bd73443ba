// Edit ▸ Optimise lenses…: the optimiser runs in the background with a progress bar, its
// result is one undoable edit, and one undo restores the document exactly.

#include <QCheckBox>
#include <QProgressBar>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

#include "main_window.h"
#include "optimise_dialog.h"
#include "ray_diagram_dock.h"
#include "scene_document.h"
#include "scene_tree.h"

using lenslab::gui::MainWindow;
using lenslab::gui::OptimiseDialog;

namespace {

// The Optimise dialog for the biconvex singlet of thick_lens_beam.json, opened in `w`.
OptimiseDialog* singlet_dialog(MainWindow& w) {
    if (!w.open_file(LENSLAB_SOURCE_DIR "/scenes/thick_lens_beam.json")) return nullptr;
    w.tree()->select_pointer("/objects/0");
    return w.optimise_selected_lens();
}

}  // namespace

class TestOptimiseDialog : public QObject {
    Q_OBJECT

private slots:
    void optimising_changes_the_lens_and_one_undo_restores_it() {
        MainWindow w;
        OptimiseDialog* dialog = singlet_dialog(w);
        QVERIFY(dialog);
        const nlohmann::json original = w.document()->json();
        // A few iterations on one field and wavelength: small for the sanitizer build.
        lenslab::gui::OptimiseChoices choices = dialog->choices();
        // It starts from the lens's EFL (the field shows three decimals).
        QVERIFY(std::abs(choices.efl_target - w.ray_diagram()->optimise_defaults().efl_target) <
                1e-3);
        choices.efl_target = 60;
        choices.fields = {0.0};
        choices.wavelengths = {587.5618};
        choices.epd = 10;
        choices.iterations = 4;
        dialog->set_choices(choices);
        QSignalSpy finished(dialog, &OptimiseDialog::finished_run);
        QVERIFY2(dialog->start(), qPrintable(dialog->status()));
        QVERIFY(dialog->running());
        QVERIFY(finished.wait(60000));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(dialog->status()));
        QCOMPARE(dialog->progress()->value(), dialog->progress()->maximum());

        // The lens bent towards the longer focal length, in one step of the undo stack.
        const nlohmann::json optimised = w.document()->json();
        QVERIFY(optimised != original);
        QVERIFY(optimised["objects"][0]["front"] != original["objects"][0]["front"]);
        QVERIFY2(w.ray_diagram()->message().contains("EFL"),
                 qPrintable(w.ray_diagram()->message()));
        QCOMPARE(w.document()->undo_stack()->count(), 1);
        w.document()->undo_stack()->undo();
        QCOMPARE(QString::fromStdString(w.document()->json().dump()),
                 QString::fromStdString(original.dump()));
        w.document()->undo_stack()->redo();
        QVERIFY(w.document()->json() == optimised);
    }

    // The dialog offers the global search (docs/optimizer.md, Global search): off by default,
    // and with a few starts the run reports runs ended, not iterations, and applies its result.
    void the_global_search_is_offered_and_runs() {
        MainWindow w;
        OptimiseDialog* dialog = singlet_dialog(w);
        QVERIFY(dialog);
        auto* starts = dialog->findChild<QSpinBox*>("global_starts");
        QVERIFY(starts);
        QCOMPARE(starts->value(), 0);
        const nlohmann::json original = w.document()->json();
        lenslab::gui::OptimiseChoices choices = dialog->choices();
        choices.efl_target = 60;
        choices.fields = {0.0};
        choices.wavelengths = {587.5618};
        choices.iterations = 2;
        choices.global_starts = 3;
        dialog->set_choices(choices);
        QCOMPARE(starts->value(), 3);
        QSignalSpy finished(dialog, &OptimiseDialog::finished_run);
        QVERIFY2(dialog->start(), qPrintable(dialog->status()));
        QCOMPARE(dialog->progress()->maximum(), 6);  // 3 starts, then up to 3 polished
        QVERIFY(finished.wait(60000));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(dialog->status()));
        QVERIFY(w.document()->json() != original);
        QCOMPARE(w.document()->undo_stack()->count(), 1);
    }

    // A lens of a model glass: its n_d and V_d vary, then the nearest catalogue glasses are
    // tried and the best put in, all one edit.
    void a_model_glass_ends_on_a_catalogue_glass() {
        QTemporaryDir dir;
        nlohmann::json scene;
        {
            QFile in(LENSLAB_SOURCE_DIR "/scenes/thick_lens_beam.json");
            QVERIFY(in.open(QIODevice::ReadOnly));
            scene = nlohmann::json::parse(in.readAll().toStdString());
        }
        scene["objects"][0]["material"] = {{"transparency", 1},
                                           {"ior", {{"model", "abbe"}, {"n_d", 1.6}, {"V_d", 50}}}};
        const QString path = dir.filePath("model_glass.json");
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(QByteArray::fromStdString(scene.dump(2)));
        out.close();
        MainWindow w;
        QVERIFY(w.open_file(path));
        w.tree()->select_pointer("/objects/0");
        OptimiseDialog* dialog = w.optimise_selected_lens();
        QVERIFY(dialog);
        QVERIFY(dialog->findChild<QCheckBox*>("vary_model_glasses")->isChecked());
        lenslab::gui::OptimiseChoices choices = dialog->choices();
        choices.efl_target = 60;
        choices.fields = {0.0};
        choices.iterations = 3;
        choices.substitute_glasses = true;
        dialog->set_choices(choices);
        QSignalSpy finished(dialog, &OptimiseDialog::finished_run);
        QVERIFY2(dialog->start(), qPrintable(dialog->status()));
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(dialog->status()));
        const nlohmann::json& material = w.document()->json()["objects"][0]["material"];
        QVERIFY2(material.contains("glass"), material.dump().c_str());
        QCOMPARE(w.document()->undo_stack()->count(), 1);
    }

    void cancelling_leaves_the_lens_unchanged() {
        MainWindow w;
        OptimiseDialog* dialog = singlet_dialog(w);
        QVERIFY(dialog);
        const nlohmann::json original = w.document()->json();
        lenslab::gui::OptimiseChoices choices = dialog->choices();
        choices.efl_target = 80;
        choices.fields = {0.0};
        choices.epd = 10;
        choices.iterations = 100000;
        dialog->set_choices(choices);
        QSignalSpy finished(dialog, &OptimiseDialog::finished_run);
        QVERIFY(dialog->start());
        dialog->cancel();
        QVERIFY(finished.wait(60000));
        QVERIFY(!finished.at(0).at(0).toBool());
        QVERIFY(w.document()->json() == original);
        QCOMPARE(w.document()->undo_stack()->count(), 0);
    }

    void without_a_lens_there_is_nothing_to_optimise() {
        MainWindow w;
        QVERIFY(w.open_file(LENSLAB_SOURCE_DIR "/scenes/thick_lens_beam.json"));
        w.tree()->select_pointer("/objects/1");  // the screen
        QTimer::singleShot(0, [] {
            if (QWidget* box = QApplication::activeModalWidget()) box->close();
        });
        QVERIFY(w.optimise_selected_lens() == nullptr);
    }
};

QTEST_MAIN(TestOptimiseDialog)
#include "test_optimise_dialog.moc"
