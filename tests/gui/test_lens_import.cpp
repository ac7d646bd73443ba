// Importing a lens file into a scene of another size (issue 41): its millimetres become the
// scene's units by the scene's length_unit_mm, and a lens larger than a scene that declares
// no unit is offered scaled to fit, by a question or without asking.

#include <QFile>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include "gui_test_support.h"
#include "main_window.h"
#include "scene_document.h"

using lenslab::gui::MainWindow;
using lenslab::gui::testing::kSmallScene;
using nlohmann::json;

namespace {

const char* const kAchromat = LENSLAB_TEST_DATA "/lensfile/data/AC254-100-A.zmx";

// The imported group's first element's centre thickness: 4 mm in the file (Thorlabs
// AC254-100-A, N-BK7 element).
double first_thickness(const MainWindow& w) {
    const json& objects = w.document()->json()["objects"];
    return objects.back()["elements"][0]["thickness"].get<double>();
}

// The small scene with `key` set to `value`, written to `dir`.
QString small_scene_with(const QTemporaryDir& dir, const char* key, const json& value) {
    QFile in(kSmallScene);
    if (!in.open(QIODevice::ReadOnly)) return {};
    json scene = json::parse(in.readAll().toStdString());
    scene[key] = value;
    const QString path = dir.filePath("scene.json");
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly)) return {};
    out.write(QByteArray::fromStdString(scene.dump(2)));
    return path;
}

}  // namespace

class TestLensImport : public QObject {
    Q_OBJECT

private slots:
    // The small scene (a 10-unit floor, no declared unit) and a lens 25.4 mm across: scaled
    // to a quarter of the scene, 1 mm = 0.05 units, by the question's "Scale to fit".
    void a_lens_larger_than_the_scene_is_offered_scaled() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        bool asked = false;
        QTimer::singleShot(0, &w, [&asked] {
            for (QWidget* top : QApplication::topLevelWidgets()) {
                auto* box = qobject_cast<QMessageBox*>(top);
                if (!box || box->objectName() != "import_scale_question") continue;
                asked = box->text().contains("25.4 mm across");
                box->findChild<QPushButton*>("import_scale_fit")->click();
            }
        });
        QVERIFY(w.import_lens(kAchromat));
        QVERIFY(asked);
        QVERIFY(std::abs(first_thickness(w) - 4 * 0.05) < 1e-12);
        const json& group = w.document()->json()["objects"].back();
        QVERIFY(std::abs(group["diameter"].get<double>() - 25.4 * 0.05) < 1e-9);
        QVERIFY2(w.status_text().contains("1 mm made 0.05 scene units"),
                 qPrintable(w.status_text()));

        // Without asking: FitScene scales, Millimetres keeps 1 unit = 1 mm.
        w.document()->undo_stack()->undo();
        QString error;
        QVERIFY(w.import_lens(kAchromat, &error, MainWindow::ImportLengths::FitScene));
        QVERIFY(std::abs(first_thickness(w) - 0.2) < 1e-12);
        w.document()->undo_stack()->undo();
        QVERIFY(w.import_lens(kAchromat, &error, MainWindow::ImportLengths::Millimetres));
        QVERIFY(std::abs(first_thickness(w) - 4) < 1e-12);
        QVERIFY(w.status_text().contains("lengths in mm"));
    }

    // A scene in centimetres (length_unit_mm 10) takes the lens in centimetres, unasked.
    void a_scene_with_a_unit_takes_the_lens_in_it() {
        QTemporaryDir dir;
        const QString path = small_scene_with(dir, "length_unit_mm", 10);
        QVERIFY(!path.isEmpty());
        MainWindow w;
        QVERIFY(w.open_file(path));
        QString error;
        QVERIFY2(w.import_lens(kAchromat, &error, MainWindow::ImportLengths::FitScene),
                 qPrintable(error));
        QVERIFY(std::abs(first_thickness(w) - 0.4) < 1e-12);
        QVERIFY(w.status_text().contains("1 mm made 0.1 scene units"));
    }
};

QTEST_MAIN(TestLensImport)
#include "test_lens_import.moc"
