#pragma once
// What the section view's tests do as a user would: open a scene in the Section tab, find
// where a ray or an object is drawn.

#include <QComboBox>
#include <QtTest>

#include "main_window.h"
#include "scene_tree.h"
#include "section_widget.h"

namespace lenslab::gui::testing {

// A window showing `scene`'s section, at the default window's size.
inline void open_section(lenslab::gui::MainWindow& w, const char* scene) {
    QString error;
    QVERIFY2(w.open_file(QString(LENSLAB_SOURCE_DIR "/scenes/") + scene, &error),
             qPrintable(error));
    QVERIFY(w.show_view("section"));
    w.resize(1280, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
}

// Where the middle of segment `k` of ray `r` is drawn.
inline QPoint segment_middle(const lenslab::gui::SectionWidget& view,
                             const lenslab::SectionRayPath& r, size_t k) {
    const lenslab::Vec3 m = (r.points[k] + r.points[k + 1]) * 0.5;
    return view.to_widget(view.section().plane.of(m)).toPoint();
}

// The middle ray of the prism scene's beam light (origin (-2.6196, 0, -0.797)): the ray
// aimed at minimum deviation.
inline const lenslab::SectionRayPath* beam_middle_ray(const lenslab::gui::SectionWidget& view) {
    const lenslab::Vec3 origin{-2.6196, 0, -0.797};
    const lenslab::SectionRayPath* best = nullptr;
    for (const lenslab::SectionRayPath& r : view.section().rays) {
        if (r.weight < 0.5 || r.points.size() < 4) continue;
        if (!best || length(r.points[0] - origin) < length(best->points[0] - origin)) best = &r;
    }
    return best && length(best->points[0] - origin) < 0.01 ? best : nullptr;
}

// Where the middle of an object's first cross-section curve is drawn.
inline QPoint drawn_middle(const lenslab::gui::SectionWidget& view, int object) {
    for (const auto& o : view.section().objects) {
        if (o.object != object) continue;
        double z = 0, y = 0;
        for (const lenslab::DiagramPoint& p : o.curves.at(0).points) z += p.z, y += p.y;
        const double n = double(o.curves.at(0).points.size());
        return view.to_widget({z / n, y / n}).toPoint();
    }
    return {-1, -1};
}

// Opens the prism scene with the prism selected, seen from above (the beam's plane).
inline void open_prism_from_above(lenslab::gui::MainWindow& w) {
    open_section(w, "prism.json");
    w.tree()->select_pointer("/objects/0");
    auto* plane = w.findChild<QComboBox*>("section_plane");
    QVERIFY(plane);
    plane->setCurrentIndex(3);  // z-x
    QCOMPARE(w.section_view()->plane_choice(), lenslab::SectionPlaneChoice::ZX);
}

}  // namespace lenslab::gui::testing
