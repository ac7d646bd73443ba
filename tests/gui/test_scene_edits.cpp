// Edits as the editor records and installs them: JSON pointers to names holding '~' and '/',
// successive edits of one field merged into one undo step, and camera moves that rebuild
// nothing (counted in BVH builds).

#include <QApplication>
#include <QColorDialog>
#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QToolButton>
#include <QTreeWidgetItemIterator>
#include <QWheelEvent>
#include <QtTest>
#include <cmath>

#include "accel/bvh_build.h"
#include "gui_test_support.h"
#include "json_pointer.h"
#include "main_window.h"
#include "number_field.h"
#include "property_panel.h"
#include "render_controller.h"
#include "scene/scene_json.h"
#include "scene_document.h"
#include "scene_tree.h"
#include "viewport.h"

using lenslab::bvh_build_count;
using lenslab::gui::MainWindow;
using lenslab::gui::NumberField;
using nlohmann::json;
namespace gui = lenslab::gui;

namespace {

using lenslab::gui::testing::field;
using lenslab::gui::testing::kSmallScene;
using lenslab::gui::testing::type_value;

const std::string kOddName = "a~b/c";

// Clicks the tree item showing `text`, as a user selects it.
bool click_item(MainWindow& w, const QString& text) {
    for (QTreeWidgetItemIterator it(w.tree()); *it; ++it) {
        if ((*it)->text(0) == text) {
            w.tree()->setCurrentItem(*it);
            return true;
        }
    }
    return false;
}

// The small test scene with its red material renamed `name` (the ball uses it).
QString write_scene_with_material(const QTemporaryDir& dir, const std::string& name) {
    QFile in(kSmallScene);
    if (!in.open(QIODevice::ReadOnly)) return {};
    json j = json::parse(in.readAll().toStdString());
    j["materials"][name] = j["materials"]["red"];
    j["materials"].erase("red");
    j["objects"][0]["material"] = name;
    const QString path = dir.filePath("odd_name.json");
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly)) return {};
    out.write(QByteArray::fromStdString(j.dump(2)));
    return path;
}

bool same_vec(const lenslab::Vec3& a, const lenslab::Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

// Exactly equal: the view renders from it, and must render what a full read would give.
bool same_camera(const lenslab::CameraSettings& a, const lenslab::CameraSettings& b) {
    return same_vec(a.position, b.position) && same_vec(a.direction, b.direction) &&
           same_vec(a.up, b.up) && a.fov_deg == b.fov_deg;
}

}  // namespace

class TestSceneEdits : public QObject {
    Q_OBJECT

private slots:
    void pointer_tokens_are_escaped_both_ways() {
        QCOMPARE(gui::escape_pointer_token("a~b/c"), std::string("a~0b~1c"));
        QCOMPARE(gui::unescape_pointer_token("a~0b~1c"), std::string("a~b/c"));
        // RFC 6901's order: "~01" is the text "~1", not '/'.
        QCOMPARE(gui::unescape_pointer_token("~01"), std::string("~1"));
        QCOMPARE(gui::escape_pointer_token("~1"), std::string("~01"));
        QCOMPARE(gui::join_pointer("/materials", QString("a~b/c")), QString("/materials/a~0b~1c"));
        QCOMPARE(gui::join_pointer("/objects", qsizetype(3)), QString("/objects/3"));
        QCOMPARE(gui::split_pointer("/materials/a~0b~1c"), QStringList({"materials", "a~b/c"}));
        QCOMPARE(gui::split_pointer(""), QStringList());
        QCOMPARE(gui::append_pointer("/materials/a~0b", "emission/intensity"),
                 std::string("/materials/a~0b/emission/intensity"));
        QCOMPARE(gui::append_pointer("/camera", ""), std::string("/camera"));
        // What the editor builds is what nlohmann::json reads back.
        const json doc{{"materials", {{kOddName, {{"specular", 0.2}}}}}};
        const json::json_pointer p(gui::append_pointer(
            gui::join_pointer("/materials", QString::fromStdString(kOddName)).toStdString(),
            "specular"));
        QCOMPARE(doc.at(p).get<double>(), 0.2);
    }

    // A material named "a~b/c": selected (no abort, a full panel), edited, undone, edited
    // again and saved with its name intact.
    void a_material_named_with_tilde_and_slash_is_edited_and_saved() {
        QTemporaryDir dir;
        const QString path = write_scene_with_material(dir, kOddName);
        QVERIFY(!path.isEmpty());
        MainWindow w;
        QString error;
        QVERIFY2(w.open_file(path, &error), qPrintable(error));
        QVERIFY(click_item(w, QString::fromStdString(kOddName)));
        QCOMPARE(w.panel()->pointer(), QString("/materials/a~0b~1c"));
        NumberField* specular = field(w, "specular");
        QVERIFY(specular);  // the panel is not empty
        QCOMPARE(specular->value(), 0.2);

        type_value(specular, 0.35);
        QCOMPARE(w.document()->json()["materials"][kOddName]["specular"].get<double>(), 0.35);
        QVERIFY(w.panel()->error_text().isEmpty());
        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->json()["materials"][kOddName]["specular"].get<double>(), 0.2);
        QCOMPARE(field(w, "specular")->value(), 0.2);
        type_value(field(w, "specular"), 0.4);

        const QString saved_path = dir.filePath("saved.json");
        QVERIFY2(w.save_file(saved_path, &error), qPrintable(error));
        QFile saved(saved_path);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        const json j = json::parse(saved.readAll().toStdString());
        QVERIFY(j["materials"].contains(kOddName));
        QCOMPARE(j["materials"].size(), size_t(2));
        QCOMPARE(j["materials"][kOddName]["specular"].get<double>(), 0.4);
        QCOMPARE(j["objects"][0]["material"].get<std::string>(), kOddName);
        // And the command line's reader takes it.
        QCOMPARE(lenslab::load_scene_file(saved_path.toStdString()).materials[0].specular, 0.4);
    }

    void successive_edits_of_one_field_are_one_undo_step() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        w.tree()->select_pointer("/objects/0");
        for (double r : {0.6, 0.7, 0.8}) type_value(field(w, "radius"), r);
        QCOMPARE(w.document()->json()["objects"][0]["radius"].get<double>(), 0.8);
        QCOMPARE(w.document()->undo_stack()->count(), 1);
        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->json()["objects"][0]["radius"].get<double>(), 0.5);
        QVERIFY(!w.document()->is_modified());
        w.document()->undo_stack()->redo();
        QCOMPARE(w.document()->json()["objects"][0]["radius"].get<double>(), 0.8);
        QCOMPARE(w.document()->scene().objects.size(), size_t(3));
    }

    void edits_of_two_fields_are_two_undo_steps() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        w.tree()->select_pointer("/objects/0");
        type_value(field(w, "radius"), 0.6);
        type_value(field(w, "center.y"), 0.75);
        type_value(field(w, "center.y"), 0.8);  // merges with the 0.75
        QCOMPARE(w.document()->undo_stack()->count(), 2);
        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->json()["objects"][0]["center"][1].get<double>(), 0.5);
        QCOMPARE(w.document()->json()["objects"][0]["radius"].get<double>(), 0.6);
        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->json()["objects"][0]["radius"].get<double>(), 0.5);
        // A field edited back to where it began leaves no step at all.
        type_value(field(w, "radius"), 0.9);
        type_value(field(w, "radius"), 0.5);
        QVERIFY(!w.document()->undo_stack()->canUndo());
    }

    // Two choices that each rewrite the whole element (same pointer) are still two fields.
    void two_fields_rewriting_one_element_are_two_steps() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        w.tree()->select_pointer("/objects/1");  // a triangle
        for (const char* name : {"field:detector", "field:photon_target"}) {
            auto* box = w.panel()->findChild<QComboBox*>(name);
            QVERIFY(box);
            box->setCurrentText("yes");
            emit box->activated(box->currentIndex());
        }
        QVERIFY(w.document()->json()["objects"][1].contains("detector"));
        QCOMPARE(w.document()->json()["objects"][1]["photon_target"].get<bool>(), true);
        QCOMPARE(w.document()->undo_stack()->count(), 2);
    }

    // An edit reads the scene once (it used to build it twice: to check, then to install).
    void an_edit_builds_the_scene_once() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        w.tree()->select_pointer("/objects/0");
        const uint64_t before = bvh_build_count();
        type_value(field(w, "radius"), 0.7);
        QCOMPARE(bvh_build_count() - before, uint64_t(1));
        w.document()->undo_stack()->undo();
        QCOMPARE(bvh_build_count() - before, uint64_t(2));
    }

    // A camera drag of 50 mouse moves (each one previewed and rendered) rebuilds no BVH: the
    // installed scene's camera alone changes. Its undo, a wheel zoom and a camera field edit
    // rebuild nothing either.
    void a_camera_drag_rebuilds_nothing_but_the_camera() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const json camera_before = w.document()->json()["camera"];
        QWidget* v = w.viewport();
        const QPoint c = v->rect().center() - QPoint(100, 0);
        QSignalSpy changes(w.document(), &gui::SceneDocument::changed);
        const uint64_t before = bvh_build_count();
        QTest::mousePress(v, Qt::LeftButton, {}, c);
        for (int i = 1; i <= 50; ++i) QTest::mouseMove(v, c + QPoint(4 * i, i % 3));
        QTest::mouseRelease(v, Qt::LeftButton, {}, c + QPoint(200, 2));
        const uint64_t drag_builds = bvh_build_count() - before;
        qInfo("BVH builds during a 50-move camera drag: %llu (document changes: %lld)",
              static_cast<unsigned long long>(drag_builds),
              static_cast<long long>(changes.count()));
        QVERIFY(changes.count() >= 50);  // every move was shown
        QVERIFY(drag_builds <= 1);
        QCOMPARE(drag_builds, uint64_t(0));
        QVERIFY(w.document()->json()["camera"] != camera_before);
        QCOMPARE(w.document()->undo_stack()->count(), 1);
        // The installed camera is what the reader makes of the document's camera block.
        const lenslab::Scene read = lenslab::scene_from_json(w.document()->json());
        QVERIFY(same_camera(w.document()->scene().camera, read.camera));
        QCOMPARE(w.document()->scene().objects.size(), size_t(3));

        QSignalSpy frames(w.renderer(), &gui::RenderController::frame_ready);
        QVERIFY(frames.wait(20000));  // the view renders the moved camera

        const uint64_t later = bvh_build_count();  // after the test's own read above
        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->json()["camera"], camera_before);
        QVERIFY(
            same_camera(w.document()->scene().camera, lenslab::camera_from_json(camera_before)));
        QWheelEvent wheel(QPointF(c), v->mapToGlobal(QPointF(c)), {}, {0, 120}, Qt::NoButton, {},
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(v, &wheel);
        QCOMPARE(w.document()->undo_stack()->count(), 1);  // the zoom replaced the undone drag
        w.tree()->select_pointer("/camera");
        type_value(field(w, "fov"), 50);
        QCOMPARE(w.document()->scene().camera.fov_deg, 50.0);
        QCOMPARE(bvh_build_count() - later, uint64_t(0));
    }

    // An edit of the render settings or of a light keeps the objects and their BVH: the
    // installed scene takes the new block, as the reader makes it, and its undo restores it.
    void render_and_light_edits_rebuild_no_bvh() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        const uint64_t before = bvh_build_count();
        w.tree()->select_pointer("/render");
        type_value(field(w, "max_depth"), 7);
        QCOMPARE(w.document()->scene().render.max_depth, 7);
        w.tree()->select_pointer("/lights/0");
        type_value(field(w, "power"), 120);
        QCOMPARE(w.document()->scene().point_lights.at(0).power, 120.0);
        json edited = w.document()->json();
        edited["lights"].push_back({{"type", "point"}, {"position", {0, 4, 0}}, {"power", 5}});
        QVERIFY(w.document()->apply(edited, "Add light", nullptr));
        QCOMPARE(w.document()->scene().lights().size(), size_t(2));
        QCOMPARE(bvh_build_count() - before, uint64_t(0));
        // A light the reader refuses is refused here too, naming it.
        edited["lights"][1]["power"] = -1;
        QString error;
        QVERIFY(!w.document()->apply(edited, "Bad light", &error));
        QVERIFY2(error.contains("lights[1].power"), qPrintable(error));
        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->scene().lights().size(), size_t(1));
        w.document()->undo_stack()->undo();
        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->scene().render.max_depth, 4);
        QCOMPARE(w.document()->scene().point_lights.at(0).power, 300.0);
        QCOMPARE(bvh_build_count() - before, uint64_t(0));
    }

    // A camera edit the reader refuses is refused without touching the installed scene.
    // The bug: the default scene's sphere and lens share "glass", so the sphere's
    // index typed as 2.4 changed the lens too. "Make unique" (a real click) gives the sphere
    // a copy of its own; the lens keeps 1.5; one undo puts the shared material back.
    void make_unique_detaches_a_shared_material() {
        MainWindow w;
        w.show();
        w.tree()->select_pointer("/objects/0");  // "glass sphere"
        auto* unique = w.panel()->findChild<QPushButton*>("material:make_unique:material");
        QVERIFY(unique);
        QVERIFY(unique->isEnabled());
        QTest::mouseClick(unique, Qt::LeftButton);
        const json& doc = w.document()->json();
        QCOMPARE(doc["objects"][0]["material"].get<std::string>(), std::string("glass 2"));
        QCOMPARE(doc["objects"][1]["material"].get<std::string>(), std::string("glass"));
        QCOMPARE(w.tree()->selected_pointer(), QString("/materials/glass 2"));
        // The new material's form is shown: its index typed in changes the sphere alone.
        NumberField* ior = field(w, "ior");
        QVERIFY(ior);
        ior->setFocus();
        ior->selectAll();
        QTest::keyClicks(ior, "2.4");
        QTest::keyClick(ior, Qt::Key_Return);
        const lenslab::Scene& s = w.document()->scene();
        QCOMPARE(s.material_of(0).index->n_d(), 2.4);
        QCOMPARE(s.material_of(1).index->n_d(), 1.5);
        w.document()->undo_stack()->undo();
        w.document()->undo_stack()->undo();
        QCOMPARE(w.document()->json()["objects"][0]["material"].get<std::string>(),
                 std::string("glass"));
        QVERIFY(!w.document()->json()["materials"].contains("glass 2"));
    }

    // Materials are created, renamed (every use follows), duplicated and deleted from the
    // material's own form; deleting one in use is refused with the users named.
    void materials_are_created_renamed_and_deleted() {
        MainWindow w;
        w.show();
        w.tree()->select_pointer("/materials/glass");
        auto* name = w.panel()->findChild<QLineEdit*>("field:material_name");
        QVERIFY(name);
        name->setFocus();
        name->selectAll();
        QTest::keyClicks(name, "crown");
        QTest::keyClick(name, Qt::Key_Return);
        QVERIFY(w.document()->json()["materials"].contains("crown"));
        QVERIFY(!w.document()->json()["materials"].contains("glass"));
        QCOMPARE(w.document()->json()["objects"][1]["material"].get<std::string>(),
                 std::string("crown"));
        QCOMPARE(w.tree()->selected_pointer(), QString("/materials/crown"));

        QTest::mouseClick(w.panel()->findChild<QPushButton*>("material:delete"), Qt::LeftButton);
        QVERIFY(w.document()->json()["materials"].contains("crown"));
        QVERIFY2(w.panel()->error_text().contains("'glass sphere', 'glass lens'"),
                 qPrintable(w.panel()->error_text()));

        QTest::mouseClick(w.panel()->findChild<QPushButton*>("material:new"), Qt::LeftButton);
        QCOMPARE(w.tree()->selected_pointer(), QString("/materials/material"));
        QTest::mouseClick(w.panel()->findChild<QPushButton*>("material:duplicate"), Qt::LeftButton);
        QCOMPARE(w.tree()->selected_pointer(), QString("/materials/material copy"));
        QTest::mouseClick(w.panel()->findChild<QPushButton*>("material:delete"), Qt::LeftButton);
        QVERIFY(!w.document()->json()["materials"].contains("material copy"));
        // The scene the view renders has the materials of the document.
        QCOMPARE(w.document()->scene().materials.size(), w.document()->json()["materials"].size());
    }

    // The default scene's floor, 128 unnamed triangles, is one folded row of the tree; an
    // object of it picked (here by pointer, as the view picks) unfolds it.
    void a_run_of_unnamed_objects_is_one_row() {
        MainWindow w;
        QTreeWidgetItem* objects = nullptr;
        for (int i = 0; i < w.tree()->topLevelItemCount(); ++i)
            if (w.tree()->topLevelItem(i)->text(0) == "Objects")
                objects = w.tree()->topLevelItem(i);
        QVERIFY(objects);
        const size_t count = w.document()->json()["objects"].size();
        QCOMPARE(objects->childCount(), 5);  // four named objects and the floor
        QTreeWidgetItem* floor = objects->child(4);
        QCOMPARE(
            floor->text(0),
            QString("%1 × triangle (objects[4] to objects[%2])").arg(count - 4).arg(count - 1));
        QVERIFY(!floor->isExpanded());
        w.tree()->select_pointer("/objects/9");
        QVERIFY(floor->isExpanded());
        QCOMPARE(w.tree()->selected_pointer(), QString("/objects/9"));
        QCOMPARE(w.panel()->pointer(), QString("/objects/9"));
    }

    // The material's glass is picked from every glass lenslab knows (the built-in ones and
    // the six makers' catalogues), by typing part of its name; an unknown name is refused
    // with the closest ones.
    void a_catalogue_glass_is_picked_by_typing_its_name() {
        MainWindow w;
        w.show();
        w.tree()->select_pointer("/materials/glass");
        auto* glass = w.panel()->findChild<QComboBox*>("field:glass");
        QVERIFY(glass);
        QVERIFY(glass->isEditable());
        QVERIFY2(glass->count() > 1000, qPrintable(QString::number(glass->count())));
        QVERIFY(glass->findText("S-BSL7") >= 0);
        QVERIFY(glass->findText("HIKARI:SF10") >= 0);  // a name two makers share
        glass->lineEdit()->setFocus();
        glass->lineEdit()->selectAll();
        QTest::keyClicks(glass->lineEdit(), "S-BSL7");
        QTest::keyClick(glass->lineEdit(), Qt::Key_Return);
        QCOMPARE(w.document()->json()["materials"]["glass"]["glass"].get<std::string>(),
                 std::string("S-BSL7"));
        // OHARA's data sheet: S-BSL7 n_d 1.51633.
        QVERIFY(std::abs(w.document()->scene().material_of(0).index->n_d() - 1.51633) < 2e-5);

        glass = w.panel()->findChild<QComboBox*>("field:glass");
        QVERIFY(glass);
        glass->lineEdit()->setFocus();
        glass->lineEdit()->selectAll();
        QTest::keyClicks(glass->lineEdit(), "NBK7");
        QTest::keyClick(glass->lineEdit(), Qt::Key_Return);
        QCOMPARE(w.document()->json()["materials"]["glass"]["glass"].get<std::string>(),
                 std::string("S-BSL7"));
        QVERIFY2(w.panel()->error_text().contains("N-BK7"), qPrintable(w.panel()->error_text()));
    }

    // A scene's own AGF catalogue: its glasses are offered as CATALOGUE:NAME and picked.
    void a_scene_catalogues_glass_is_offered() {
        QTemporaryDir dir;
        const QString path = dir.filePath("own_glass.json");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray::fromStdString(
            json{{"glass_catalogues", json::array({LENSLAB_SOURCE_DIR "/tests/cli/data/user.agf"})},
                 {"camera", {{"position", {0, 0, 5}}, {"look_at", {0, 0, 0}}}},
                 {"render", {{"width", 32}, {"height", 24}}},
                 {"materials", {{"glass", {{"transparency", 1}, {"ior", 1.5}}}}},
                 {"objects", json::array({json{{"type", "sphere"},
                                               {"center", {0, 0, 0}},
                                               {"radius", 1},
                                               {"material", "glass"}}})}}
                .dump()));
        file.close();
        MainWindow w;
        QString error;
        QVERIFY2(w.open_file(path, &error), qPrintable(error));
        w.tree()->select_pointer("/materials/glass");
        auto* glass = w.panel()->findChild<QComboBox*>("field:glass");
        QVERIFY(glass);
        const int at = glass->findText("USER:MY-CROWN");
        QVERIFY(at > 0);
        QVERIFY(at < glass->findText("S-BSL7"));  // before the makers', as lookups take them
        glass->setCurrentIndex(at);
        emit glass->activated(at);
        QCOMPARE(w.document()->json()["materials"]["glass"]["glass"].get<std::string>(),
                 std::string("USER:MY-CROWN"));
    }

    // Fractions (transparency, specular) have a slider beside their field: a drag shows its
    // value and commits once when released; a key commits at once.
    void a_fraction_has_a_slider() {
        MainWindow w;
        w.show();
        w.tree()->select_pointer("/materials/red_plastic");
        auto* slider = w.panel()->findChild<QSlider*>("slider:specular");
        QVERIFY(slider);
        const double before =
            w.document()->json()["materials"]["red_plastic"].value("specular", 0.0);
        QCOMPARE(slider->value(), int(std::lround(100 * before)));
        slider->setSliderDown(true);
        slider->setValue(40);
        QCOMPARE(field(w, "specular")->value(), 0.4);
        QCOMPARE(w.document()->json()["materials"]["red_plastic"].value("specular", 0.0), before);
        slider->setSliderDown(false);  // released
        QCOMPARE(w.document()->json()["materials"]["red_plastic"]["specular"].get<double>(), 0.4);
        slider = w.panel()->findChild<QSlider*>("slider:specular");
        QVERIFY(slider);
        slider->setFocus();
        QTest::keyClick(slider, Qt::Key_Right);
        QCOMPARE(w.document()->json()["materials"]["red_plastic"]["specular"].get<double>(), 0.41);
    }

    // A colour's three numbers have a swatch that opens a colour picker; the picked sRGB
    // colour is written as linear RGB (sRGB 128 is linear 0.2158).
    void a_colour_is_picked() {
        MainWindow w;
        w.show();
        w.tree()->select_pointer("/materials/red_plastic");
        auto* swatch = w.panel()->findChild<QToolButton*>("colour:color");
        QVERIFY(swatch);
        QTest::mouseClick(swatch, Qt::LeftButton);
        auto* picker = w.panel()->findChild<QColorDialog*>("colour_picker");
        QVERIFY(picker);
        picker->setCurrentColor(QColor(255, 128, 0));
        picker->accept();
        const json c = w.document()->json()["materials"]["red_plastic"]["color"];
        QCOMPARE(c[0].get<double>(), 1.0);
        QVERIFY(std::abs(c[1].get<double>() - 0.21586) < 1e-4);
        QCOMPARE(c[2].get<double>(), 0.0);
    }

    void a_bad_camera_edit_is_refused() {
        MainWindow w;
        QVERIFY(w.open_file(kSmallScene));
        const json before = w.document()->json();
        json edited = before;
        edited["camera"]["look_at"] = edited["camera"]["position"];
        QString error;
        QVERIFY(!w.document()->apply(edited, "bad camera", &error));
        QCOMPARE(error, QString("camera.look_at: must differ from position"));
        QCOMPARE(w.document()->json(), before);
        QVERIFY(!w.document()->undo_stack()->canUndo());
    }
};

QTEST_MAIN(TestSceneEdits)
#include "test_scene_edits.moc"
