// The editor's forms against the declarations they are generated from (param_spec.h): each
// declared field is there (named "field:KEY"), shows the declared default, and takes exactly
// the declared range and choices. And the gather radius takes 0, its "auto".

#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <vector>

#include "main_window.h"
#include "number_field.h"
#include "property_panel.h"
#include "scene/box_json.h"
#include "scene/camera_spec.h"
#include "scene/lens_group_json.h"
#include "scene/light_spec.h"
#include "scene/material_spec.h"
#include "scene/medium.h"
#include "scene/mesh_json.h"
#include "scene/object_spec.h"
#include "scene/planar_json.h"
#include "scene/render_settings_spec.h"
#include "scene/surface_json.h"
#include "scene/surface_shapes.h"
#include "scene_document.h"
#include "scene_tree.h"

using lenslab::ElementSpec;
using lenslab::ParamKind;
using lenslab::ParamSpec;
using lenslab::gui::MainWindow;
using lenslab::gui::NumberField;
using nlohmann::json;

namespace {

// A scene whose camera and render block leave every optional key out, so each field shows
// its default.
QString write_bare_scene(QTemporaryDir& dir, const json& render) {
    const QString path = dir.filePath("bare.json");
    QFile file(path);
    file.open(QIODevice::WriteOnly);
    const json scene = {
        {"camera", {{"position", {0, 1, 4}}, {"look_at", {0, 0, 0}}}},
        {"render", render},
        {"materials", {{"grey", {{"color", 0.5}}}}},
        {"objects",
         {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 0.5}, {"material", "grey"}}}},
        {"lights", {{{"type", "point"}, {"position", {1, 3, 2}}, {"power", 100}}}}};
    file.write(QByteArray::fromStdString(scene.dump(2)));
    return path;
}

// Every labelled parameter of `spec` (but `skip`) against the form now shown; `prefix` is
// where a nested element's fields are ("detector/", "front/").
void check_form(MainWindow& w, const ElementSpec& spec, const std::vector<std::string>& skip,
                const std::string& prefix = "") {
    for (const ParamSpec& p : spec.params) {
        if (p.label.empty() || std::find(skip.begin(), skip.end(), p.key) != skip.end()) continue;
        const QString name = QString::fromStdString("field:" + prefix + p.key);
        const QByteArray where = QByteArray::fromStdString(spec.name + "." + p.key);
        switch (p.kind) {
            case ParamKind::WholeNumber:
            case ParamKind::Number:
            case ParamKind::Fraction: {
                auto* box = w.panel()->findChild<NumberField*>(name);
                QVERIFY2(box, where.constData());
                // A required key is in the file, with no default to show.
                if (p.fallback.is_number()) {
                    QVERIFY2(box->value() == p.fallback.get<double>(), where.constData());
                }
                // The declared ends themselves (an exclusive one is refused by the field).
                if (p.min) QVERIFY2(box->minimum() == p.min->value, where.constData());
                if (p.max) QVERIFY2(box->maximum() == p.max->value, where.constData());
                // Every field explains itself from its declaration.
                QVERIFY2(box->toolTip().contains(QString::fromStdString(p.doc)), where.constData());
                if (p.kind == ParamKind::Fraction && !p.min) QCOMPARE(box->minimum(), 0.0);
                if (p.kind == ParamKind::Fraction) QCOMPARE(box->maximum(), 1.0);
                break;
            }
            case ParamKind::Choice: {
                auto* box = w.panel()->findChild<QComboBox*>(name);
                QVERIFY2(box, where.constData());
                QStringList choices;
                for (const std::string& c : p.choices) choices << QString::fromStdString(c);
                QStringList shown;
                for (int i = 0; i < box->count(); ++i) shown << box->itemText(i);
                QCOMPARE(shown, choices);
                QCOMPARE(box->currentText(), QString::fromStdString(p.fallback.get<std::string>()));
                break;
            }
            case ParamKind::Boolean: {
                auto* box = w.panel()->findChild<QComboBox*>(name);
                QVERIFY2(box, where.constData());
                const QString shown = !p.fallback.is_boolean() ? QString("auto")
                                      : p.fallback.get<bool>() ? QString("yes")
                                                               : QString("no");
                QCOMPARE(box->currentText(), shown);
                break;
            }
            case ParamKind::String:
            case ParamKind::Array:  // a formula, or numbers as a comma-separated list
                QVERIFY2(w.panel()->findChild<QLineEdit*>(name), where.constData());
                break;
            default: {  // colours, points, directions: three boxes, key.x, key.y, key.z
                auto* x = w.panel()->findChild<NumberField*>(name + ".x");
                QVERIFY2(x, where.constData());
                if (p.kind == ParamKind::Colour || p.kind == ParamKind::Albedo)
                    QCOMPARE(x->minimum(), 0.0);
                if (p.kind == ParamKind::Albedo) QCOMPARE(x->maximum(), 1.0);
                break;
            }
        }
    }
}

// Opens a scene holding `objects` (with a material "grey") and selects the first object.
void open_objects(MainWindow& w, QTemporaryDir& dir, const json& objects) {
    const QString path = dir.filePath("objects.json");
    QFile file(path);
    file.open(QIODevice::WriteOnly);
    const json scene = {{"camera", {{"position", {0, 1, 4}}, {"look_at", {0, 0, 0}}}},
                        {"materials", {{"grey", {{"color", 0.5}}}}},
                        {"objects", objects}};
    file.write(QByteArray::fromStdString(scene.dump(2)));
    file.close();
    QString error;
    QVERIFY2(w.open_file(path, &error), qPrintable(error));
    w.tree()->select_pointer("/objects/0");
}

}  // namespace

class TestPropertyForms : public QObject {
    Q_OBJECT

private slots:
    void render_form_follows_the_declaration() {
        QTemporaryDir dir;
        MainWindow w;
        QString error;
        QVERIFY2(w.open_file(write_bare_scene(dir, json::object()), &error), qPrintable(error));
        w.tree()->select_pointer("/render");
        check_form(w, lenslab::render_settings_spec(), {});
    }

    void camera_form_follows_the_declaration() {
        QTemporaryDir dir;
        MainWindow w;
        QVERIFY(w.open_file(write_bare_scene(dir, json::object())));
        w.tree()->select_pointer("/camera");
        check_form(w, lenslab::camera_spec(), {"direction"});  // the file gives look_at
    }

    void light_sphere_and_material_forms_follow_their_declarations() {
        QTemporaryDir dir;
        MainWindow w;
        QVERIFY(w.open_file(write_bare_scene(dir, json::object())));
        w.tree()->select_pointer("/lights/0");
        check_form(w, lenslab::point_light_spec(), {"color"});  // the spectrum's choice shows it
        w.tree()->select_pointer("/objects/0");
        check_form(w, lenslab::sphere_spec(), {});
        w.tree()->select_pointer("/materials/grey");
        // A melt's departures belong to a catalogue glass (below).
        check_form(w, lenslab::material_spec(), {"delta_n_d", "delta_V_d"});
        QVERIFY(!w.panel()->findChild<NumberField*>("field:delta_n_d"));
        json glass = w.document()->json();
        glass["materials"]["glass"] = {{"transparency", 1}, {"glass", "N-BK7"}};
        QTemporaryDir other;
        const QString path = other.filePath("glass.json");
        QFile file(path);
        file.open(QIODevice::WriteOnly);
        file.write(QByteArray::fromStdString(glass.dump(2)));
        file.close();
        MainWindow g;
        QVERIFY(g.open_file(path));
        g.tree()->select_pointer("/materials/glass");
        for (const char* key : {"delta_n_d", "delta_V_d"}) {
            QVERIFY2(g.panel()->findChild<NumberField*>(QString("field:") + key), key);
        }
    }

    // A beam's and a laser's forms hold the slit's and the fan's fields (light_spec.cpp).
    void beam_and_laser_forms_show_the_slit_and_the_fan() {
        QTemporaryDir dir;
        const QString path = dir.filePath("lights.json");
        QFile file(path);
        file.open(QIODevice::WriteOnly);
        const json scene = {{"camera", {{"position", {0, 1, 4}}, {"look_at", {0, 0, 0}}}},
                            {"lights",
                             {{{"type", "beam"},
                               {"origin", {0, 0, 0}},
                               {"direction", {1, 0, 0}},
                               {"radius", 0.3},
                               {"power", 1},
                               {"slit_width", 0.1}},
                              {{"type", "laser"},
                               {"position", {0, 1, 0}},
                               {"direction", {1, 0, 0}},
                               {"radius", 0.01},
                               {"power", 1},
                               {"fan_angle", 30}}}}};
        file.write(QByteArray::fromStdString(scene.dump(2)));
        file.close();
        MainWindow w;
        QString error;
        QVERIFY2(w.open_file(path, &error), qPrintable(error));
        w.tree()->select_pointer("/lights/0");
        check_form(w, lenslab::beam_spec(), {"color", "slit_width"});
        auto* slit = w.panel()->findChild<NumberField*>("field:slit_width");
        QVERIFY(slit);
        QCOMPARE(slit->value(), 0.1);
        w.tree()->select_pointer("/lights/1");
        check_form(w, lenslab::laser_spec(), {"fan_angle"});
        auto* fan = w.panel()->findChild<NumberField*>("field:fan_angle");
        QVERIFY(fan);
        QCOMPARE(fan->value(), 30.0);
    }

    // A material's index profile: each GRIN profile, picked, writes a block the scene reader
    // takes and shows that profile's fields with its values; "uniform" removes the block.
    void grin_form_follows_the_profile() {
        QTemporaryDir dir;
        MainWindow w;
        const json glass = {{"transparency", 1}, {"ior", 1.5}};
        open_objects(
            w, dir,
            {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 0.5}, {"material", glass}}});
        for (const std::string& profile : lenslab::grin_spec().param("profile").choices) {
            const QByteArray where = QByteArray::fromStdString(profile);
            auto* box = w.panel()->findChild<QComboBox*>("field:material/grin/profile");
            QVERIFY2(box, where.constData());
            box->setCurrentText(QString::fromStdString(profile));
            emit box->activated(box->currentIndex());
            const json& material = w.document()->json()["objects"][0]["material"];
            QCOMPARE(material.value("grin", json()), lenslab::grin_starting_block(profile));
            QVERIFY2(w.document()->scene().material_of(0).grin, where.constData());
            for (const std::string& key : lenslab::grin_keys_of(profile)) {
                const QString name = QString::fromStdString("field:material/grin/" + key);
                const ParamSpec& p = lenslab::grin_spec().param(key);
                if (p.kind == ParamKind::String) {
                    auto* edit = w.panel()->findChild<QLineEdit*>(name);
                    QVERIFY2(edit, qPrintable(name));
                    QCOMPARE(edit->text().toStdString(), material["grin"][key].get<std::string>());
                } else if (p.kind == ParamKind::Direction) {
                    QVERIFY2(w.panel()->findChild<NumberField*>(name + ".z"), qPrintable(name));
                } else {
                    auto* field = w.panel()->findChild<NumberField*>(name);
                    QVERIFY2(field, qPrintable(name));
                    QCOMPARE(field->value(), material["grin"][key].get<double>());
                }
            }
        }
        auto* box = w.panel()->findChild<QComboBox*>("field:material/grin/profile");
        box->setCurrentText("uniform");
        emit box->activated(box->currentIndex());
        QVERIFY(!w.document()->json()["objects"][0]["material"].contains("grin"));
        QVERIFY(!w.panel()->findChild<NumberField*>("field:material/grin/n0"));
    }

    // A declared type with no form of its own (the box) gets its declaration's fields.
    void box_form_falls_back_to_its_declaration() {
        QTemporaryDir dir;
        const QString path = dir.filePath("box.json");
        QFile file(path);
        file.open(QIODevice::WriteOnly);
        const json scene = {{"camera", {{"position", {0, 1, 4}}, {"look_at", {0, 0, 0}}}},
                            {"materials", {{"grey", {{"color", 0.5}}}}},
                            {"objects",
                             {{{"type", "box"},
                               {"center", {0, 0, 0}},
                               {"size", {1, 2, 3}},
                               {"material", "grey"}}}}};
        file.write(QByteArray::fromStdString(scene.dump(2)));
        file.close();
        MainWindow w;
        QString error;
        QVERIFY2(w.open_file(path, &error), qPrintable(error));
        w.tree()->select_pointer("/objects/0");
        check_form(w, lenslab::box_spec(), {});
    }

    // A lens face switched to each shape of the table becomes a valid surface of that shape
    // (the document refuses an invalid one), and its form shows the shape's declared fields.
    void every_surface_shape_switches_and_has_its_form() {
        QTemporaryDir dir;
        MainWindow w;
        open_objects(w, dir,
                     {{{"type", "lens"},
                       {"center", {0, 0, 0}},
                       {"axis", {0, 0, 1}},
                       {"thickness", 0.5},
                       {"diameter", 1},
                       {"front", {{"shape", "asphere"}, {"radius", 2}, {"coefficients", {0.001}}}},
                       {"back", {{"shape", "sphere"}, {"radius", -2}}},
                       {"material", "grey"}}});
        for (const lenslab::SurfaceShapeEntry& e : lenslab::surface_shapes()) {
            auto* shape = w.panel()->findChild<QComboBox*>("field:front/shape");
            QVERIFY(shape);
            shape->setCurrentText(QString::fromStdString(e.name));
            QCOMPARE(shape->currentText(), QString::fromStdString(e.name));
            emit shape->activated(shape->currentIndex());
            QCOMPARE(w.document()->json()["objects"][0]["front"]["shape"].get<std::string>(),
                     e.name);
            check_form(w, e.spec(), {}, "front/");
        }
    }

    // The lens's two forms, its faces, the lens group and its elements, the mesh, the prism
    // and the detector block: each form takes its fields from the declaration.
    void lens_forms_follow_the_declaration() {
        QTemporaryDir dir;
        {
            MainWindow w;
            open_objects(
                w, dir,
                {{{"type", "lens"},
                  {"center", {0, 0, 0}},
                  {"axis", {0, 0, 1}},
                  {"thickness", 0.5},
                  {"diameter", 1},
                  {"front", {{"shape", "conic"}, {"radius", 2}, {"k", -1}}},
                  {"back", {{"shape", "asphere"}, {"radius", -2}, {"coefficients", {0.0}}}},
                  {"material", "grey"}}});
            check_form(w, lenslab::lens_spec(), {"curvature_radius", "aperture_radius"});
            check_form(w, lenslab::conic_surface_spec(), {}, "front/");
            check_form(w, lenslab::asphere_surface_spec(), {}, "back/");
            QVERIFY(!w.panel()->findChild<NumberField*>("field:curvature_radius"));
        }
        MainWindow w;
        open_objects(w, dir,
                     {{{"type", "lens"},
                       {"center", {0, 0, 0}},
                       {"axis", {0, 0, 1}},
                       {"curvature_radius", 1},
                       {"aperture_radius", 0.5},
                       {"material", "grey"}}});
        check_form(w, lenslab::lens_spec(),
                   {"thickness", "diameter", "x_axis", "decenter_x", "decenter_y", "tilt_x",
                    "tilt_y", "tilt_z"});
    }

    void lens_group_form_follows_the_declaration() {
        QTemporaryDir dir;
        MainWindow w;
        open_objects(w, dir,
                     {{{"type", "lens_group"},
                       {"vertex", {0, 0, 0}},
                       {"axis", {0, 0, 1}},
                       {"diameter", 1},
                       {"elements",
                        {{{"front", {{"shape", "sphere"}, {"radius", 2}}},
                          {"thickness", 0.5},
                          {"material", "grey"}},
                         {{"front", {{"shape", "sphere"}, {"radius", -2}}},
                          {"back", {{"shape", "flat"}}},
                          {"thickness", 0.3},
                          {"material", "grey"}}}}}});
        // The group's photon_target is not in its form (each element is an object of its own).
        check_form(w, lenslab::lens_group_spec(), {"photon_target"});
        check_form(w, lenslab::lens_group_element_spec(), {}, "elements/0/");
        check_form(w, lenslab::sphere_surface_spec(), {}, "elements/0/front/");
    }

    void lens_group_mirror_form_follows_the_declaration() {
        QTemporaryDir dir;
        MainWindow w;
        open_objects(w, dir,
                     {{{"type", "lens_group"},
                       {"vertex", {0, 0, 0}},
                       {"axis", {0, 0, 1}},
                       {"diameter", 1},
                       {"elements",
                        {{{"mirror", {{"shape", "conic"}, {"radius", -4}, {"k", -1}}},
                          {"gap", 1},
                          {"material", "grey"}},
                         {{"front", {{"shape", "sphere"}, {"radius", -2}}},
                          {"back", {{"shape", "flat"}}},
                          {"thickness", 0.3},
                          {"material", "grey"}}}}}});
        // A mirror before another element needs a gap: the form shows the file's, not the
        // default.
        check_form(w, lenslab::lens_group_mirror_spec(), {"gap"}, "elements/0/");
        auto* gap = w.panel()->findChild<NumberField*>("field:elements/0/gap");
        QVERIFY(gap);
        QCOMPARE(gap->value(), 1.0);
        check_form(w, lenslab::conic_surface_spec(), {}, "elements/0/mirror/");
        check_form(w, lenslab::lens_group_element_spec(), {"gap"}, "elements/1/");
    }

    void mesh_and_prism_forms_follow_their_declarations() {
        QTemporaryDir dir;
        {
            MainWindow w;
            open_objects(w, dir,
                         {{{"type", "mesh"},
                           {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                           {"faces", {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}},
                           {"material", "grey"}}});
            check_form(w, lenslab::mesh_spec(), {});
        }
        MainWindow w;
        open_objects(w, dir,
                     {{{"type", "prism"},
                       {"side", 1},
                       {"height", 1},
                       {"center", {0, 0, 0}},
                       {"material", "grey"}}});
        check_form(w, lenslab::prism_spec(), {});
    }

    void detector_form_follows_the_declaration() {
        QTemporaryDir dir;
        MainWindow w;
        open_objects(w, dir,
                     {{{"type", "disc"},
                       {"center", {0, 0, 0}},
                       {"normal", {0, 0, 1}},
                       {"radius", 1},
                       {"detector", json::object()},
                       {"material", "grey"}}});
        check_form(w, lenslab::disc_spec(), {});
        check_form(w, lenslab::detector_spec(), {}, "detector/");
        const ParamSpec& cells = lenslab::detector_spec().param("resolution");
        auto* box = w.panel()->findChild<NumberField*>("field:detector/resolution");
        QVERIFY(box);
        QCOMPARE(box->minimum(), cells.min->value);
        QCOMPARE(box->maximum(), cells.max->value);
        QCOMPARE(box->value(), cells.fallback.get<double>());
    }

    // A closed shape's medium: its fields follow the atmosphere's declaration; a shape with a
    // medium and no material (only the medium's edge) opens without an error.
    void medium_form_follows_the_declaration() {
        QTemporaryDir dir;
        MainWindow w;
        open_objects(w, dir,
                     {{{"type", "box"},
                       {"center", {0, 0, 0}},
                       {"size", {1, 1, 1}},
                       {"medium", json::object()}}});
        QVERIFY2(w.panel()->error_text().isEmpty(), qPrintable(w.panel()->error_text()));
        check_form(w, lenslab::medium_spec(), {}, "medium/");
    }

    // Must-show: 0 means "auto" for the gather radius, and the field can be set to it.
    void gather_radius_field_accepts_zero_auto() {
        QTemporaryDir dir;
        MainWindow w;
        QVERIFY(
            w.open_file(write_bare_scene(dir, {{"integrator", "photon_map"}, {"radius", 0.05}})));
        w.tree()->select_pointer("/render");
        auto* radius = w.panel()->findChild<NumberField*>("field:radius");
        QVERIFY(radius);
        QCOMPARE(radius->value(), 0.05);
        QCOMPARE(radius->minimum(), 0.0);
        radius->setText(QString::number(0.0));
        emit radius->editingFinished();
        QVERIFY2(w.panel()->error_text().isEmpty(), qPrintable(w.panel()->error_text()));
        QCOMPARE(w.document()->json()["render"]["radius"].get<double>(), 0.0);
        QCOMPARE(w.document()->scene().render.radius, 0.0);
    }
};

QTEST_MAIN(TestPropertyForms)
#include "test_property_forms.moc"
