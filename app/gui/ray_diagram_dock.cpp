#include "ray_diagram_dock.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QScrollArea>
#include <QSpinBox>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "analysis/figures/curve_figures.h"
#include "analysis/figures/diffraction_maps.h"
#include "analysis/figures/field_figures.h"
#include "analysis/report/lens_report.h"
#include "bench_figure_view.h"
#include "diagram_painter.h"
#include "json_pointer.h"
#include "map_image_view.h"
#include "optics/glass.h"
#include "scene_document.h"
#include "util/scene_error.h"

namespace lenslab::gui {

namespace {

// Fewer rays than the command line's report: the dock redraws on every edit.
constexpr int kSpotRings = 8;
// The pause after an edit before the bench figures are recomputed: typing in a number field
// recomputes once, not per key.
constexpr int kBenchDelayMs = 150;
constexpr int kLayoutTab = 0;

// `figure` in a scroll area: a dock too small for it at a readable size scrolls it.
QScrollArea* scrolled(BenchFigureView* figure) {
    auto* area = new QScrollArea(figure->parentWidget());
    area->setWidgetResizable(true);  // filled when larger than the figure's least size
    area->setFrameShape(QFrame::NoFrame);
    area->setWidget(figure);
    return area;
}

// The spot tab's table: one line a field, then one a wavelength.
QString spot_numbers_text(const SpotDiagrams& spots) {
    const auto number = [](double v) { return QString::number(v, 'g', 4); };
    QStringList lines;
    for (const FieldSpots& field : spots.fields) {
        lines << QObject::tr("field %1°: polychromatic RMS %2, Airy %3")
                     .arg(number(field.field), number(field.polychromatic.rms_radius),
                          number(field.airy_radius));
        for (const WavelengthSpot& spot : field.spots) {
            lines << QObject::tr("    %1 nm: RMS %2, GEO %3, vignetted %4 of %5")
                         .arg(QString::number(spot.wavelength_nm, 'f', 2),
                              number(spot.spot.rms_radius), number(spot.spot.geometric_radius))
                         .arg(spot.vignetted)
                         .arg(spot.rays);
        }
    }
    return lines.join('\n');
}

QString default_wavelengths_text() {
    return QString("%1, %2, %3").arg(kLineF).arg(kLineD).arg(kLineC);
}

}  // namespace

RayDiagramView::RayDiagramView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(240, 80);
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
    : QDockWidget(tr("Bench"), parent),
      m_document(document),
      m_view(new RayDiagramView(this)),
      m_message(new QLabel(this)),
      m_tabs(new QTabWidget(this)),
      m_fields(new QLineEdit("0, 5", this)),
      m_wavelengths(new QLineEdit(default_wavelengths_text(), this)),
      m_epd(new QDoubleSpinBox(this)),
      m_stop(new QSpinBox(this)),
      m_ray_aiming(new QComboBox(this)),
      m_spot_numbers(new QLabel(this)),
      m_spot_view(new BenchFigureView(this)),
      m_fan_view(new BenchFigureView(this)),
      m_curve_view(new BenchFigureView(this)),
      m_mtf_view(new BenchFigureView(this)),
      m_psf_view(new MapImageView(this)),
      m_wavefront_view(new MapImageView(this)),
      m_bench_timer(new QTimer(this)) {
    setObjectName("ray_diagram_dock");
    m_message->setObjectName("ray_diagram_message");
    m_message->setWordWrap(true);
    m_spot_numbers->setObjectName("bench_spot_numbers");
    m_spot_numbers->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* spots = new QWidget(this);
    auto* spot_layout = new QHBoxLayout(spots);
    spot_layout->setContentsMargins(0, 0, 0, 0);
    spot_layout->addWidget(scrolled(m_spot_view), 1);
    spot_layout->addWidget(m_spot_numbers, 0, Qt::AlignTop);
    m_tabs->setObjectName("bench_tabs");
    m_tabs->addTab(m_view, tr("Layout"));
    m_tabs->addTab(spots, tr("Spots"));
    m_tabs->addTab(scrolled(m_fan_view), tr("Fans"));
    m_tabs->addTab(scrolled(m_curve_view), tr("Field curves"));
    m_tabs->addTab(scrolled(m_mtf_view), tr("MTF"));
    m_tabs->addTab(m_psf_view, tr("PSF"));
    m_tabs->addTab(m_wavefront_view, tr("Wavefront"));
    m_psf_view->setObjectName("bench_psf");
    m_wavefront_view->setObjectName("bench_wavefront");
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_message);
    layout->addWidget(make_controls());
    layout->addWidget(m_tabs, 1);
    setWidget(body);
    m_bench_timer->setSingleShot(true);
    m_bench_timer->setInterval(kBenchDelayMs);
    connect(m_bench_timer, &QTimer::timeout, this, &RayDiagramDock::update_bench);
    connect(m_tabs, &QTabWidget::currentChanged, this, &RayDiagramDock::schedule_bench);
    connect(m_document, &SceneDocument::changed, this, &RayDiagramDock::refresh);
    refresh();
}

QWidget* RayDiagramDock::make_controls() {
    auto* controls = new QWidget(this);
    auto* row = new QHBoxLayout(controls);
    row->setContentsMargins(0, 0, 0, 0);
    m_fields->setObjectName("bench_fields");
    m_fields->setToolTip(tr("Field angles in degrees, comma-separated"));
    m_wavelengths->setObjectName("bench_wavelengths");
    m_wavelengths->setToolTip(
        tr("Wavelengths in nm, comma-separated; the middle one is the "
           "primary (default: the F, d and C lines)"));
    m_epd->setObjectName("bench_epd");
    m_epd->setRange(0, 1e6);
    m_epd->setDecimals(3);
    m_epd->setSpecialValueText(tr("auto"));
    m_epd->setToolTip(tr("Entrance pupil diameter; auto: the stop surface's rim"));
    m_stop->setObjectName("bench_stop");
    m_stop->setRange(1, 999);
    m_stop->setToolTip(tr("The aperture stop: a surface, counted from 1 along the light"));
    row->addWidget(new QLabel(tr("Fields"), controls));
    row->addWidget(m_fields, 2);
    row->addWidget(new QLabel(tr("Wavelengths"), controls));
    row->addWidget(m_wavelengths, 3);
    row->addWidget(new QLabel(tr("EPD"), controls));
    row->addWidget(m_epd, 1);
    m_ray_aiming->setObjectName("bench_ray_aiming");
    for (RayAiming aiming : {RayAiming::Real, RayAiming::Paraxial})
        m_ray_aiming->addItem(ray_aiming_name(aiming), static_cast<int>(aiming));
    m_ray_aiming->setToolTip(
        tr("How real rays are aimed at a pupil point: real, through the real stop; paraxial, "
           "at the paraxial entrance pupil (Zemax's default)"));
    row->addWidget(new QLabel(tr("Stop"), controls));
    row->addWidget(m_stop);
    row->addWidget(new QLabel(tr("Aim"), controls));
    row->addWidget(m_ray_aiming);
    const auto settings_changed = [this] {
        m_bench_stale = true;
        schedule_bench();
    };
    connect(m_fields, &QLineEdit::editingFinished, this, settings_changed);
    connect(m_wavelengths, &QLineEdit::editingFinished, this, settings_changed);
    connect(m_epd, &QDoubleSpinBox::valueChanged, this, settings_changed);
    connect(m_stop, &QSpinBox::valueChanged, this, settings_changed);
    connect(m_ray_aiming, &QComboBox::currentIndexChanged, this, settings_changed);
    return controls;
}

OptimiseChoices RayDiagramDock::optimise_defaults() const {
    OptimiseChoices c;
    c.efl_target = m_efl;
    c.epd = m_epd->value() > 0 ? m_epd->value() : m_pupil;
    c.stop = m_stop->value();
    c.fields = number_list(m_fields->text().toStdString()).value_or(c.fields);
    c.wavelengths = number_list(m_wavelengths->text().toStdString()).value_or(c.wavelengths);
    return c;
}

void RayDiagramDock::schedule_bench() {
    // The figures cost more than the layout: only for a tab that shows them.
    if (m_bench_stale && m_tabs->currentIndex() != kLayoutTab) m_bench_timer->start();
}

bool RayDiagramDock::read_settings(QString& error) {
    const auto fields = number_list(m_fields->text().toStdString());
    const auto wavelengths = number_list(m_wavelengths->text().toStdString());
    if (!fields) {
        error = tr("Fields: numbers in degrees, comma-separated");
        return false;
    }
    if (!wavelengths) {
        error = tr("Wavelengths: numbers in nm, comma-separated");
        return false;
    }
    for (double angle : *fields) {
        if (!(std::abs(angle) < 90.0)) {
            error = tr("Fields: %1 degrees is not a field angle").arg(angle);
            return false;
        }
    }
    for (double nm : *wavelengths) {
        if (!(nm > 0)) {
            error = tr("Wavelengths: %1 is not a wavelength in nm").arg(nm);
            return false;
        }
    }
    m_settings.fields = fields->empty() ? std::vector<double>{0.0} : *fields;
    m_settings.wavelengths = *wavelengths;
    m_settings.epd = m_epd->value();
    m_settings.stop = m_stop->value();
    m_settings.ray_aiming = static_cast<RayAiming>(m_ray_aiming->currentData().toInt());
    return true;
}

void RayDiagramDock::update_bench() {
    m_bench_timer->stop();
    m_bench_stale = false;
    m_bench = BenchFigures{};
    QString error;
    if (m_lens < 0) {
        error = tr("Select a lens to see its bench figures.");
    } else if (read_settings(error)) {
        m_settings.psf = m_tabs->currentWidget() == m_psf_view;
        m_settings.wavefront = m_tabs->currentWidget() == m_wavefront_view;
        try {
            const OpticalSystem system = build_optical_system(m_document->scene(), m_lens);
            if (m_settings.stop > int(system.surfaces.size())) {
                error = tr("Stop: the system has %1 surfaces").arg(system.surfaces.size());
            } else {
                m_bench = compute_bench_figures(system, m_settings);
            }
        } catch (const lenslab::Error& e) {
            error = QString::fromStdString(e.what());
        }
    }
    for (const std::string& e : m_bench.errors) {
        error += (error.isEmpty() ? "" : "\n") + QString::fromStdString(e);
    }
    show_bench();
    if (!error.isEmpty()) {
        m_spot_numbers->setText(m_spot_numbers->text() +
                                (m_spot_numbers->text().isEmpty() ? "" : "\n\n") + error);
    }
}

void RayDiagramDock::show_bench() {
    // Labels in degrees and "units": a scene declares no length unit.
    const std::string unit, field_unit = "deg";
    const BenchFigures& b = m_bench;
    m_spot_numbers->setText(b.spots ? spot_numbers_text(*b.spots) : QString());
    if (b.spots) {
        m_spot_view->set_figure(spot_diagram_figure(*b.spots, unit, field_unit),
                                field_figure_width(int(b.spots->fields.size())));
    } else {
        m_spot_view->set_figure(std::nullopt);
    }
    if (b.fans) {
        m_fan_view->set_figure(ray_fan_figure(*b.fans, unit, field_unit), field_figure_width(2));
    } else {
        m_fan_view->set_figure(std::nullopt);
    }
    if (b.curves) {
        m_curve_view->set_figure(field_curves_figure(*b.curves, unit, field_unit),
                                 field_figure_width(2));
    } else {
        m_curve_view->set_figure(std::nullopt);
    }
    m_psf_view->set_image(
        b.psfs.empty() ? QImage()
                       : to_qimage(psf_map_image(b.psfs, ColourScale::Log, "units", field_unit)));
    m_wavefront_view->set_image(
        b.wavefronts && !b.wavefronts->figures.empty()
            ? to_qimage(opd_map_image(*b.wavefronts, b.wavefronts->figures.front().wavelength_nm,
                                      field_unit))
            : QImage());
    if (b.mtf) {
        m_mtf_view->set_figure(field_mtf_figure(*b.mtf, "mm", "deg"), field_figure_width(1));
    } else if (b.diffraction) {
        m_mtf_view->set_figure(mtf_figure(*b.diffraction, "mm"), field_figure_width(1));
    } else {
        m_mtf_view->set_figure(std::nullopt);
    }
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
    m_lens = index >= 0 && scene.objects[index].type == ObjectType::Lens ? index : -1;
    m_bench_stale = true;
    schedule_bench();
    if (m_lens < 0) {
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
        m_efl = report.paraxial.efl;
        m_pupil = report.first_order.entrance_pupil.diameter;
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
