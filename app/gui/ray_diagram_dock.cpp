#include "ray_diagram_dock.h"

#include <QPainter>
#include <QPainterPath>
#include <QVBoxLayout>

#include "analysis/lens_report.h"
#include "json_pointer.h"
#include "scene/scene_error.h"
#include "scene_document.h"

namespace lenslab::gui {

namespace {

QColor qcolour(const DiagramColour& c) { return QColor(c.r, c.g, c.b); }

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
    painter.fillRect(rect(), Qt::white);
    if (!m_diagram) return;
    const RayDiagram& d = *m_diagram;
    painter.setRenderHint(QPainter::Antialiasing);
    const double top = 28, bottom = 30, margin = 12;
    const DiagramView v = fit_diagram(d, width(), height(), margin, top, bottom);
    const auto at = [&](const DiagramPoint& p) { return QPointF(v.x(p.z), v.y(p.y)); };

    // Rays leaving a diverging lens run out of the frame: clip them to the diagram's box.
    painter.setClipRect(
        QRectF(QPointF(v.x(d.z_min), v.y(d.y_max)), QPointF(v.x(d.z_max), v.y(d.y_min))));
    for (const DiagramPath& p : d.paths) {
        QPolygonF polygon;
        for (const DiagramPoint& q : p.points) polygon << at(q);
        QPen pen(qcolour(p.stroke), p.width);
        if (p.dash > 0) pen.setDashPattern({p.dash / p.width, 0.6 * p.dash / p.width});
        painter.setPen(pen);
        if (p.filled) {
            QColor fill = qcolour(p.fill);
            fill.setAlphaF(p.fill_opacity);
            painter.setBrush(fill);
        } else {
            painter.setBrush(Qt::NoBrush);
        }
        if (p.closed) {
            painter.drawPolygon(polygon);
        } else {
            painter.drawPolyline(polygon);
        }
    }
    painter.setClipping(false);
    painter.setPen(Qt::NoPen);
    for (const DiagramDot& dot : d.dots) {
        painter.setBrush(qcolour(dot.colour));
        painter.drawEllipse(at(dot.at), dot.radius, dot.radius);
    }
    QFont font = painter.font();
    for (const DiagramText& t : d.labels) {
        font.setPixelSize(int(t.size));
        painter.setFont(font);
        painter.setPen(qcolour(t.colour));
        const QPointF p = at(t.at) + QPointF(t.dx, t.dy);
        const double w = painter.fontMetrics().horizontalAdvance(QString::fromStdString(t.text));
        const double x = t.anchor == DiagramText::Anchor::Start ? p.x()
                         : t.anchor == DiagramText::Anchor::End ? p.x() - w
                                                                : p.x() - 0.5 * w;
        painter.drawText(QPointF(x, p.y()), QString::fromStdString(t.text));
    }
    // Legend (top) and scale bar (bottom left).
    font.setPixelSize(11);
    painter.setFont(font);
    double x = margin;
    for (const LegendEntry& e : d.legend) {
        painter.setPen(QPen(qcolour(e.colour), 2.5));
        painter.drawLine(QPointF(x, 14), QPointF(x + 22, 14));
        painter.setPen(Qt::black);
        painter.drawText(QPointF(x + 27, 18), QString::fromStdString(e.text));
        x += 40 + painter.fontMetrics().horizontalAdvance(QString::fromStdString(e.text));
    }
    const double bar = d.scale_bar * v.scale;
    const double y = height() - 12;
    painter.setPen(QPen(Qt::black, 2));
    painter.drawLine(QPointF(margin, y), QPointF(margin + bar, y));
    painter.drawLine(QPointF(margin, y - 4), QPointF(margin, y + 4));
    painter.drawLine(QPointF(margin + bar, y - 4), QPointF(margin + bar, y + 4));
    painter.drawText(QPointF(margin + bar + 6, y + 4), QString::fromStdString(d.scale_bar_label));
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
