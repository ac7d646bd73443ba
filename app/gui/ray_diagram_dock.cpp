#include "ray_diagram_dock.h"

#include <QVBoxLayout>

#include "analysis/lens_report.h"
#include "diagram_painter.h"
#include "json_pointer.h"
#include "scene/scene_error.h"
#include "scene_document.h"

namespace lenslab::gui {

namespace {

// Fewer rays than the command line's report: the dock redraws on every edit.
constexpr int kSpotRings = 8;

}  // namespace

RayDiagramView::RayDiagramView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(360, 180);
    setObjectName("ray_diagram_view");
}

void RayDiagramView::set_diagram(std::optional<RayDiagram> diagram) {
    m_diagram = std::move(diagram);
    update();
}

void RayDiagramView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    if (!m_diagram) {
        painter.fillRect(rect(), Qt::white);
        return;
    }
    paint_diagram(painter, *m_diagram, size(), fit_diagram_to(*m_diagram, size()));
}

RayDiagramDock::RayDiagramDock(SceneDocument* document, QWidget* parent)
    : QDockWidget(tr("Ray diagram"), parent),
      m_document(document),
      m_view(new RayDiagramView(this)),
      m_message(new QLabel(this)) {
    setObjectName("ray_diagram_dock");
    m_message->setObjectName("ray_diagram_message");
    m_message->setWordWrap(true);
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_message);
    layout->addWidget(m_view, 1);
    setWidget(body);
    connect(m_document, &SceneDocument::changed, this, &RayDiagramDock::refresh);
    refresh();
}

void RayDiagramDock::show_pointer(const QString& pointer) {
    m_pointer = pointer;
    refresh();
}

void RayDiagramDock::refresh() {
    const QStringList tokens = split_pointer(m_pointer);  // {"objects", "3"}: an object
    bool is_object = tokens.size() == 2 && tokens[0] == "objects";
    int entry = is_object ? tokens[1].toInt(&is_object) : -1;
    if (!is_object) entry = -1;
    const Scene& scene = m_document->scene();
    // The first scene object made from that entry of the file (a lens group makes several).
    int index = -1;
    for (int i = 0; i < int(scene.objects.size()) && index < 0 && entry >= 0; ++i) {
        if (scene.objects[i].source == entry) index = i;
    }
    if (index < 0 || scene.objects[index].type != ObjectType::Lens) {
        m_view->set_diagram(std::nullopt);
        m_message->setText(tr("Select a lens to see the ray diagram of the lenses on its axis."));
        return;
    }
    try {
        const OpticalSystem system = build_optical_system(scene, index);
        LensReportOptions options;
        options.spot_rings = kSpotRings;
        const LensReport report = analyze_lens_system(system, options);
        m_view->set_diagram(make_ray_diagram(system, report));
        m_message->setText(
            tr("%1 lens(es) · EFL %2 · BFL %3 · RMS spot %4 at best focus (%5 nm; scene units)")
                .arg(system.elements.size())
                .arg(report.paraxial.efl, 0, 'f', 3)
                .arg(report.paraxial.bfl, 0, 'f', 3)
                .arg(report.spot_best.rms_radius, 0, 'g', 3)
                .arg(report.wavelength_nm, 0, 'f', 2));
    } catch (const lenslab::Error& e) {  // a SceneError, or a formula undefined where traced
        m_view->set_diagram(std::nullopt);
        m_message->setText(tr("No ray diagram: %1").arg(QString::fromStdString(e.what())));
    }
}

}  // namespace lenslab::gui
