// The scene's atmosphere in the editor: added from the Edit menu with its declaration's
// example, edited through a form generated from that declaration (scene/medium.h), every step
// undoable, removed from its form or with Edit ▸ Delete, none of it rebuilding the objects'
// BVH; and the view renders it with its usual integrator.

#include <QAction>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTreeWidgetItemIterator>
#include <QtTest>
#include <algorithm>
#include <memory>
#include <vector>

#include "accel/bvh_build.h"
#include "gui_test_support.h"
#include "main_window.h"
#include "number_field.h"
#include "property_panel.h"
#include "render/integrator_names.h"
#include "render_controller.h"
#include "scene/medium.h"
#include "scene_document.h"
#include "scene_tree.h"

using lenslab::ParamKind;
using lenslab::ParamSpec;
using lenslab::gui::MainWindow;
using lenslab::gui::NumberField;
using lenslab::gui::RenderController;
using nlohmann::json;

namespace {

using lenslab::gui::testing::field;
using lenslab::gui::testing::integrator_of_fresh_frame;
using lenslab::gui::testing::kSmallScene;

bool tree_shows(MainWindow& w, const QString& pointer) {
    for (QTreeWidgetItemIterator it(w.tree()); *it; ++it) {
        if ((*it)->data(0, Qt::UserRole).toString() == pointer) return true;
    }
    return false;
}

const json& atmosphere_json(MainWindow& w) { return w.document()->json()["atmosphere"]; }

}  // namespace

class TestAtmosphereEdits : public QObject {
    Q_OBJECT

private slots:
    void an_atmosphere_is_added_edited_undone_and_removed() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        QVERIFY(!w.document()->json().contains("atmosphere"));
        QVERIFY(!tree_shows(w, "/atmosphere"));
        const uint64_t builds = lenslab::bvh_build_count();

        QAction* add = w.findChild<QAction*>("add_atmosphere");
        QVERIFY(add);
        add->trigger();
        QCOMPARE(atmosphere_json(w), lenslab::medium_spec().example);
        QVERIFY(w.document()->scene().atmosphere);
        QVERIFY(tree_shows(w, "/atmosphere"));
        QCOMPARE(w.tree()->selected_pointer(), QString("/atmosphere"));
        QCOMPARE(w.panel()->pointer(), QString("/atmosphere"));

        // Every labelled key of the declaration has its field, showing the example's value
        // or the declared default.
        for (const ParamSpec& p : lenslab::medium_spec().params) {
            if (p.label.empty()) continue;
            if (p.kind == ParamKind::String) {  // the density's formula: a line of text
                auto* text =
                    w.panel()->findChild<QLineEdit*>("field:" + QString::fromStdString(p.key));
                QVERIFY2(text, qPrintable(QString::fromStdString(p.key)));
                QCOMPARE(text->text().toStdString(), p.fallback.get<std::string>());
                continue;
            }
            const bool triple = p.kind == ParamKind::Colour;
            const QString name = QString::fromStdString(p.key) + (triple ? ".x" : "");
            NumberField* box = field(w, name);
            QVERIFY2(box, qPrintable(name));
            const json& example = lenslab::medium_spec().example;
            const json shown = example.contains(p.key) ? example[p.key] : p.fallback;
            const double first = shown.is_array() ? shown[0].get<double>() : shown.get<double>();
            QCOMPARE(box->value(), first);
        }

        // The green band's scattering: a grey number becomes a triple. The three boxes are
        // labelled with their bands (typing in an unlabelled one tinted the fog unawares).
        for (const char* band : {"R", "G", "B"}) {
            auto* label = w.panel()->findChild<QLabel*>(QString("band:scattering.") + band);
            QVERIFY2(label, band);
            QCOMPARE(label->text(), QString(band));
        }
        NumberField* green = field(w, "scattering.y");
        QVERIFY(green);
        green->setText("0.2");
        emit green->editingFinished();
        QCOMPARE(atmosphere_json(w)["scattering"], json::array({0.05, 0.2, 0.05}));
        QVERIFY(!w.document()->scene().atmosphere->is_grey());
        QCOMPARE(atmosphere_json(w)["g"].get<double>(), 0.3);

        // Undo: the example again, in the document, the scene and the form.
        w.document()->undo_stack()->undo();
        QCOMPARE(atmosphere_json(w), lenslab::medium_spec().example);
        QVERIFY(w.document()->scene().atmosphere->is_grey());
        QCOMPARE(field(w, "scattering.y")->value(), 0.05);
        // Undo again: clear air, and no atmosphere in the tree.
        w.document()->undo_stack()->undo();
        QVERIFY(!w.document()->json().contains("atmosphere"));
        QVERIFY(!w.document()->scene().atmosphere);
        QVERIFY(!tree_shows(w, "/atmosphere"));

        // Redone, then removed with the form's button (one undo step).
        w.document()->undo_stack()->redo();
        w.document()->undo_stack()->redo();
        QCOMPARE(atmosphere_json(w)["scattering"], json::array({0.05, 0.2, 0.05}));
        w.tree()->select_pointer("/atmosphere");
        auto* remove = w.panel()->findChild<QPushButton*>("atmosphere:remove");
        QVERIFY(remove);
        QTest::mouseClick(remove, Qt::LeftButton);
        QVERIFY(!w.document()->json().contains("atmosphere"));
        QVERIFY(!w.document()->scene().atmosphere);
        QVERIFY(!tree_shows(w, "/atmosphere"));
        QCOMPARE(w.panel()->pointer(), QString());
        w.document()->undo_stack()->undo();
        QCOMPARE(atmosphere_json(w)["scattering"], json::array({0.05, 0.2, 0.05}));

        // Edit ▸ Delete removes it too.
        w.tree()->select_pointer("/atmosphere");
        w.delete_selected();
        QVERIFY(!w.document()->json().contains("atmosphere"));
        // Fog is no part of the objects' acceleration structure.
        QCOMPARE(lenslab::bvh_build_count() - builds, uint64_t(0));
    }

    // Adding an atmosphere to a scene that has one selects it and changes nothing.
    void adding_a_second_atmosphere_selects_the_first() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        w.add_atmosphere();
        NumberField* g = field(w, "g");
        QVERIFY(g);
        g->setText("-0.5");
        emit g->editingFinished();
        const int steps = w.document()->undo_stack()->count();
        w.tree()->select_pointer("/camera");
        w.add_atmosphere();
        QCOMPARE(w.document()->undo_stack()->count(), steps);
        QCOMPARE(atmosphere_json(w)["g"].get<double>(), -0.5);
        QCOMPARE(w.tree()->selected_pointer(), QString("/atmosphere"));
    }

    // Fog with no absorption and no scattering is clear air to the renderer (read as none, the
    // same rule as the scene reader's) while the file keeps it.
    void a_clear_atmosphere_is_none() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        w.add_atmosphere();
        QVERIFY(w.document()->set_value(json::json_pointer("/atmosphere/scattering"), 0, "clear",
                                        nullptr));
        QVERIFY(w.document()->json().contains("atmosphere"));
        QVERIFY(!w.document()->scene().atmosphere);
        w.document()->undo_stack()->undo();
        QVERIFY(w.document()->scene().atmosphere);
    }

    // sppm renders media, so the view keeps its integrator for a scene with fog.
    void the_view_renders_an_atmosphere_with_its_usual_integrator() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        w.add_atmosphere();
        QCOMPARE(integrator_of_fresh_frame(w),
                 QString::fromUtf8(lenslab::integrators::kView.data(),
                                   qsizetype(lenslab::integrators::kView.size())));
    }

    // The trial's finding: a 0.1 W laser added to the default scene was lost after Add
    // atmosphere, the lamp's veil a snow of single volume photons at the view's size. With
    // the added atmosphere's volume neighbours the veil is smooth after 8 passes and the beam's
    // green stands out of it (before: 2.2% of the veil's pixels were specks, now 0.25%).
    void a_faint_beam_shows_through_an_added_atmosphere() {
        MainWindow w;
        QVERIFY(w.open_file(LENSLAB_SOURCE_DIR "/scenes/default.json"));
        json scene = w.document()->json();
        scene["lights"].push_back({{"type", "laser"},
                                   {"position", {-2.5, 1.5, 0.5}},
                                   {"direction", {1, 0, 0}},
                                   {"radius", 0.02},
                                   {"power", 0.1},
                                   {"wavelength", 532}});
        QString error;
        QVERIFY2(w.document()->apply(scene, "Add laser", &error), qPrintable(error));
        w.add_atmosphere();

        RenderController renderer(nullptr, 160);  // the 800 x 600 scene at 160 x 120
        renderer.set_max_passes(8);
        QImage frame;
        QObject::connect(&renderer, &RenderController::frame_ready, &renderer,
                         [&](const QImage& image, int passes) {
                             if (passes == 8) frame = image;
                         });
        renderer.restart(w.document()->scene(), 0);
        QTRY_VERIFY_WITH_TIMEOUT(!frame.isNull(), 120000);
        QCOMPARE(frame.size(), QSize(160, 120));

        // The back wall's veil above the beam: pixels brighter than its median by 0.15.
        std::vector<double> veil;
        for (int y = 5; y < 25; ++y) {
            for (int x = 20; x < 140; ++x) veil.push_back(QColor(frame.pixel(x, y)).valueF());
        }
        std::vector<double> sorted = veil;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        const double median = sorted[sorted.size() / 2];
        const double specks = double(std::count_if(veil.begin(), veil.end(),
                                                   [&](double v) { return v > median + 0.15; })) /
                              veil.size();
        QVERIFY2(specks < 0.01, qPrintable(QString::number(specks)));

        // The beam: the row of the wall with the most green over red and blue.
        double beam = 0, wall = 0;
        for (int y = 15; y < 45; ++y) {
            double excess = 0;
            for (int x = 60; x < 140; ++x) {
                const QColor c(frame.pixel(x, y));
                excess += (c.greenF() - 0.5 * (c.redF() + c.blueF())) / 80;
            }
            if (excess > beam) beam = excess;
            if (y < 25) wall = std::max(wall, excess);
        }
        QVERIFY2(beam > 0.03 && beam > 4 * wall,
                 qPrintable(QString("beam %1, wall %2").arg(beam).arg(wall)));
    }
};

QTEST_MAIN(TestAtmosphereEdits)
#include "test_atmosphere_edits.moc"
