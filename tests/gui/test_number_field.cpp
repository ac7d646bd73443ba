// The number field (app/gui/number_field.h) alone, then in the property panel through real
// key and wheel events: each case is a way typing once lost or changed a number (issue 16).
#include <QApplication>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>
#include <nlohmann/json.hpp>

#include "main_window.h"
#include "number_field.h"
#include "property_panel.h"
#include "scene/param_spec.h"
#include "scene_document.h"
#include "scene_tree.h"

using lenslab::ParamSpec;
using lenslab::gui::format_shown;
using lenslab::gui::MainWindow;
using lenslab::gui::NumberField;
using lenslab::gui::parse_number;
using nlohmann::json;

namespace {

NumberField* field(MainWindow& w, const QString& name) {
    return w.panel()->findChild<NumberField*>("field:" + name);
}

// Replaces the field's text by typing, as a person does after selecting it all.
void retype(QWidget* w, const QString& text) {
    QApplication::processEvents();  // a rebuilt form is shown from the event loop
    w->setFocus(Qt::TabFocusReason);
    QTest::keyClick(w, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(w, text);
}

void wheel(QWidget* w, int notches) {
    const QPointF at(w->width() / 2.0, w->height() / 2.0);
    QWheelEvent event(at, w->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &event);
}

// A shown, active editor with a lens added (the panel shows it) and `render` merged in.
void open_with_lens(MainWindow& w, const json& render = json::object()) {
    w.show();
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    json j = w.document()->json();
    j["render"].update(render);
    QVERIFY(w.document()->apply(j, "setup", nullptr));
    w.add_element("lens");
    QApplication::processEvents();
}

json lens(MainWindow& w) { return w.document()->json()["objects"].back(); }

}  // namespace

class TestNumberField : public QObject {
    Q_OBJECT

private slots:
    void parses_what_people_write() {
        const ParamSpec plain = lenslab::number_param("x", 0);
        QCOMPARE(parse_number("-12e-1", plain).value.value(), -1.2);
        QCOMPARE(parse_number(" +2.5 ", plain).value.value(), 2.5);
        QCOMPARE(parse_number("-2", plain).value.value(), -2.0);
        // Refused, never stripped to another number.
        QVERIFY(!parse_number("-1,2", plain).value);
        QVERIFY(parse_number("-1,2", plain).problem.contains(",2"));
        QVERIFY(!parse_number("1.5mm", plain).value);
        QVERIFY(parse_number("1.5mm", plain).problem.contains("mm"));
        QVERIFY(!parse_number("", plain).value);
        QVERIFY(!parse_number("abc", plain).value);
        QVERIFY(!parse_number("nan", plain).value);
        QVERIFY(!parse_number("inf", plain).value);
    }

    void accepts_the_declared_unit_only() {
        const ParamSpec angle = lenslab::number_param("fov", 40).in_unit("degrees");
        QCOMPARE(parse_number("30 deg", angle).value.value(), 30.0);
        QCOMPARE(parse_number("30degrees", angle).value.value(), 30.0);
        QVERIFY(!parse_number("30 mm", angle).value);
        QVERIFY(parse_number("30 mm", angle).problem.contains("degrees"));
        const ParamSpec length = lenslab::number_param("d", 1).in_unit("mm");
        QCOMPARE(parse_number("1.5mm", length).value.value(), 1.5);
        QCOMPARE(parse_number("1.5 mm", length).value.value(), 1.5);
    }

    void checks_the_declared_range_and_kind() {
        const ParamSpec positive = lenslab::number_param("r", 1).above(0);
        QVERIFY(!parse_number("0", positive).value);
        QVERIFY(!parse_number("-2", positive).problem.isEmpty());
        const ParamSpec whole = lenslab::whole_param("n", 4, 1, 16);
        QVERIFY(parse_number("2.5", whole).problem.contains("whole"));
        QVERIFY(parse_number("17", whole).problem.contains("16"));
        QCOMPARE(parse_number("16", whole).value.value(), 16.0);
    }

    void shows_six_significant_digits_without_trailing_zeros() {
        QCOMPARE(format_shown(0.06), QString("0.06"));
        QCOMPARE(format_shown(-20.0), QString("-20"));
        QCOMPARE(format_shown(2.0 / 3.0), QString("0.666667"));
        QCOMPARE(format_shown(-0.0), QString("0"));
        NumberField f(lenslab::number_param("radius", 0));
        f.setValue(0.06);
        QCOMPARE(f.text(), QString("0.06"));
    }

    void a_refused_text_is_red_with_its_reason_and_keeps_the_value() {
        NumberField f(lenslab::number_param("x", 0).describe("the x"));
        f.setValue(1.5);
        QSignalSpy committed(&f, &NumberField::committed);
        QTest::keyClick(&f, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(&f, "-1,2");
        QTest::keyClick(&f, Qt::Key_Return);
        QCOMPARE(committed.count(), 0);
        QCOMPARE(f.value(), 1.5);
        QVERIFY(!f.problem().isEmpty());
        QVERIFY(f.styleSheet().contains("background"));
        QVERIFY(f.toolTip().contains(f.problem()));
        QVERIFY(f.toolTip().contains("the x"));
        QTest::keyClick(&f, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(&f, "-12e-1");
        QTest::keyClick(&f, Qt::Key_Return);
        QCOMPARE(committed.count(), 1);
        QCOMPARE(f.value(), -1.2);
        QCOMPARE(f.text(), QString("-1.2"));
        QVERIFY(f.problem().isEmpty());
        QVERIFY(f.styleSheet().isEmpty());
    }

    // Escape gives up what was typed: the last good value is back, a refusal cleared,
    // nothing committed.
    void escape_restores_the_last_good_value() {
        NumberField f(lenslab::number_param("x", 0));
        f.setValue(1.5);
        QSignalSpy committed(&f, &NumberField::committed);
        QTest::keyClick(&f, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(&f, "2.75");
        QTest::keyClick(&f, Qt::Key_Escape);
        QCOMPARE(f.text(), QString("1.5"));
        QTest::keyClick(&f, Qt::Key_Return);
        QCOMPARE(committed.count(), 0);
        QTest::keyClick(&f, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(&f, "1.5mm");
        QTest::keyClick(&f, Qt::Key_Return);
        QVERIFY(!f.problem().isEmpty());
        QTest::keyClick(&f, Qt::Key_Escape);
        QVERIFY(f.problem().isEmpty());
        QVERIFY(f.styleSheet().isEmpty());
        QCOMPARE(f.text(), QString("1.5"));
        QCOMPARE(f.value(), 1.5);
        QCOMPARE(committed.count(), 0);
    }

    // The asphere's coefficients are read as number fields read numbers: "1e-3x" or "0.5mm"
    // refused (not stripped to 0.001 or 0.5), scientific notation taken.
    void a_coefficient_list_reads_numbers_strictly() {
        MainWindow w;
        open_with_lens(w);
        const json before = w.document()->json();
        QVERIFY(w.document()->set_value(
            json::json_pointer("/objects/" + std::to_string(before["objects"].size() - 1) +
                               "/front"),
            {{"shape", "asphere"}, {"radius", 2}, {"k", 0}, {"coefficients", {0.0}}}, "asphere",
            nullptr));
        QApplication::processEvents();
        auto* list = w.panel()->findChild<QLineEdit*>("field:front/coefficients");
        QVERIFY(list);
        retype(list, "1e-3, 0.5mm");
        QTest::keyClick(list, Qt::Key_Return);
        QCOMPARE(lens(w)["front"]["coefficients"], json::array({0.0}));
        auto* problem = w.panel()->findChild<QLabel*>("list_error:front/coefficients");
        QVERIFY(problem);
        QVERIFY2(problem->text().contains("'mm'"), qPrintable(problem->text()));
        retype(list, "1e-3, -2.5E-5");
        QTest::keyClick(list, Qt::Key_Return);
        QCOMPARE(lens(w)["front"]["coefficients"], json::array({1e-3, -2.5e-5}));
    }

    // Centre x 0.3, Tab, 0.95, Tab: the panel rebuilt after the first commit, and the second
    // number used to go nowhere.
    void tab_after_a_commit_keeps_typing_in_the_next_field() {
        MainWindow w;
        open_with_lens(w);
        NumberField* x = field(w, "center.x");
        QVERIFY(x);
        retype(x, "0.3");
        QVERIFY(x->hasFocus());
        QTest::keyClick(x, Qt::Key_Tab);
        QCOMPARE(lens(w)["center"][0].get<double>(), 0.3);
        QWidget* next = QApplication::focusWidget();
        QVERIFY(next);
        QCOMPARE(next->objectName(), QString("field:center.y"));
        QTest::keyClicks(next, "0.95");
        QTest::keyClick(next, Qt::Key_Tab);
        QCOMPARE(lens(w)["center"][1].get<double>(), 0.95);
        QCOMPARE(lens(w)["center"][0].get<double>(), 0.3);
        QVERIFY(QApplication::focusWidget());
        QCOMPARE(QApplication::focusWidget()->objectName(), QString("field:center.z"));
    }

    void a_comma_is_refused_and_the_scene_is_unchanged() {
        MainWindow w;
        open_with_lens(w);
        const json before = w.document()->json();
        NumberField* x = field(w, "center.x");
        const double kept = x->value();
        retype(x, "-1,2");
        QTest::keyClick(x, Qt::Key_Return);
        QCOMPARE(w.document()->json(), before);
        QVERIFY(!x->problem().isEmpty());
        QVERIFY(x->styleSheet().contains("background"));
        QCOMPARE(x->value(), kept);
        QVERIFY(w.panel()->error_text().contains(x->problem()));
    }

    void scientific_notation_commits_its_number() {
        MainWindow w;
        open_with_lens(w);
        NumberField* x = field(w, "center.x");
        retype(x, "-12e-1");
        QTest::keyClick(x, Qt::Key_Return);
        QCOMPARE(lens(w)["center"][0].get<double>(), -1.2);
        QCOMPARE(field(w, "center.x")->text(), QString("-1.2"));
    }

    void a_minus_is_kept_or_refused_never_dropped() {
        MainWindow w;
        open_with_lens(w);
        // A surface's radius is signed: -2 is -2.
        NumberField* front = field(w, "front/radius");
        QVERIFY(front);
        retype(front, "-2");
        QTest::keyClick(front, Qt::Key_Return);
        QCOMPARE(lens(w)["front"]["radius"].get<double>(), -2.0);
        // A unitless length with "mm" after it is refused, not read as 1.5.
        NumberField* thickness = field(w, "thickness");
        QVERIFY(thickness);
        retype(thickness, "1.5mm");
        QTest::keyClick(thickness, Qt::Key_Return);
        QCOMPARE(lens(w)["thickness"].get<double>(), 0.3);
        QVERIFY(thickness->problem().contains("mm"));
        // A thickness is declared above 0: -2 is refused with the reason.
        retype(thickness, "-2");
        QTest::keyClick(thickness, Qt::Key_Return);
        QCOMPARE(lens(w)["thickness"].get<double>(), 0.3);
        QVERIFY(!thickness->problem().isEmpty());
    }

    void the_wheel_acts_only_on_a_focused_field() {
        MainWindow w;
        open_with_lens(w, {{"integrator", "photon_map"}, {"radius", 0.06}});
        w.tree()->select_pointer("/render");
        QApplication::processEvents();
        NumberField* radius = field(w, "radius");
        QVERIFY(radius);
        QCOMPARE(radius->text(), QString("0.06"));
        w.tree()->setFocus();
        wheel(radius, 1);
        QCOMPARE(w.document()->json()["render"]["radius"].get<double>(), 0.06);
        QCOMPARE(radius->text(), QString("0.06"));
        // Focused, one notch is one unit in the second significant digit.
        radius->setFocus();
        QVERIFY(radius->hasFocus());
        wheel(radius, 1);
        QCOMPARE(w.document()->json()["render"]["radius"].get<double>(), 0.061);
        QVERIFY(QApplication::focusWidget());
        QCOMPARE(QApplication::focusWidget()->objectName(), QString("field:radius"));
    }

    void vector_fields_are_wide_enough_and_explained() {
        MainWindow w;
        open_with_lens(w);
        NumberField* x = field(w, "center.x");
        x->setValue(-20);
        QCOMPARE(x->text(), QString("-20"));
        QVERIFY(x->minimumWidth() >= x->fontMetrics().horizontalAdvance("-0.000000"));
        QVERIFY(!x->toolTip().isEmpty());
        // All three fit in the panel as it opens: none runs past its right edge (the z field
        // of a lens's centre was cut off beside the long labels of the lens's form).
        QApplication::processEvents();
        QWidget* shown = w.panel()->parentWidget();  // the scroll area's viewport
        QVERIFY(shown);
        for (const char* name : {"center.x", "center.y", "center.z", "axis.z"}) {
            NumberField* f = field(w, name);
            QVERIFY2(f, name);
            const int right = f->mapTo(shown, QPoint(f->width(), 0)).x();
            QVERIFY2(right <= shown->width(),
                     qPrintable(
                         QString("%1 ends at %2 of %3").arg(name).arg(right).arg(shown->width())));
        }
    }
};

QTEST_MAIN(TestNumberField)
#include "test_number_field.moc"
