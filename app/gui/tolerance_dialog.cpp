#include "tolerance_dialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QThread>
#include <QVBoxLayout>

#include "analysis/system/optical_system.h"
#include "bench_figure_view.h"
#include "bench_figures.h"
#include "optimize/lens_design.h"
#include "optimize/tolerance_figure.h"
#include "scene_document.h"
#include "util/error.h"
#include "util/scene_error.h"

namespace lenslab::gui {

namespace {

// Thrown from the Monte Carlo's progress callback to end the run early.
struct ToleranceCancelled {};

QString cell_text(const std::optional<double>& v) {
    return v ? QString::number(*v, 'f', 5) : QObject::tr("(fails)");
}

QDoubleSpinBox* millimetres(QWidget* parent) {
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(0, 10);
    box->setDecimals(4);
    box->setSingleStep(0.01);
    box->setPrefix(QString::fromUtf8("± "));
    return box;
}

}  // namespace

nlohmann::json tolerance_design_json(const nlohmann::json& scene, const ToleranceChoices& c) {
    nlohmann::json design = {{"system", scene},
                             {"stop", c.optics.stop},
                             {"epd", c.optics.epd},
                             {"fields", c.optics.fields},
                             {"tolerances",
                              {{"radius", c.radius},
                               {"thickness", c.thickness},
                               {"air_gap", c.air_gap},
                               {"decenter", c.decenter},
                               {"tilt", c.tilt},
                               {"trials", c.trials}}}};
    if (!c.optics.wavelengths.empty()) design["wavelengths"] = c.optics.wavelengths;
    return design;
}

ToleranceDialog::ToleranceDialog(SceneDocument* document, int lens, QWidget* parent)
    : QDialog(parent),
      m_document(document),
      m_lens(lens),
      m_fields(new QLineEdit(this)),
      m_epd(new QDoubleSpinBox(this)),
      m_stop(new QSpinBox(this)),
      m_radius(millimetres(this)),
      m_thickness(millimetres(this)),
      m_air_gap(millimetres(this)),
      m_decenter(millimetres(this)),
      m_tilt(millimetres(this)),
      m_trials(new QSpinBox(this)),
      m_progress(new QProgressBar(this)),
      m_status(new QLabel(this)),
      m_table(new QTableWidget(0, 3, this)),
      m_figure(new BenchFigureView(this)),
      m_run(new QPushButton(tr("Run"), this)),
      m_close(new QPushButton(tr("Close"), this)) {
    setObjectName("tolerance_dialog");
    setWindowTitle(tr("Tolerance lenses"));
    m_epd->setRange(1e-3, 1e6);
    m_epd->setDecimals(3);
    m_stop->setRange(1, 999);
    m_trials->setObjectName("trials");
    m_trials->setRange(1, 1000000);
    m_status->setObjectName("tolerance_summary");
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_table->setObjectName("sensitivity");
    m_table->setHorizontalHeaderLabels({tr("Tolerance"), tr("RMS spot at −"), tr("at +")});
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    auto* form = new QFormLayout;
    form->addRow(tr("Fields (deg)"), m_fields);
    form->addRow(tr("Entrance pupil diameter"), m_epd);
    form->addRow(tr("Stop surface"), m_stop);
    form->addRow(tr("Radius error (mm)"), m_radius);
    form->addRow(tr("Thickness error (mm)"), m_thickness);
    form->addRow(tr("Air gap error (mm)"), m_air_gap);
    form->addRow(tr("Lens decentre (mm)"), m_decenter);
    form->addRow(tr("Lens tilt (degrees)"), m_tilt);
    form->addRow(tr("Monte Carlo lenses"), m_trials);
    auto* buttons = new QDialogButtonBox(this);
    buttons->addButton(m_run, QDialogButtonBox::AcceptRole);
    buttons->addButton(m_close, QDialogButtonBox::RejectRole);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_progress);
    layout->addWidget(m_table, 1);
    m_figure->setObjectName("tolerance_figure");
    m_figure->set_least_zoom(0);  // fitted to the dialog; double-click opens it full size
    layout->addWidget(m_figure, 2);
    layout->addWidget(m_status);
    layout->addWidget(buttons);
    resize(640, 760);
    connect(m_run, &QPushButton::clicked, this, &ToleranceDialog::start);
    connect(m_close, &QPushButton::clicked, this, [this] {
        if (running()) {
            cancel();
        } else {
            reject();
        }
    });
    set_choices(ToleranceChoices{});
}

ToleranceDialog::~ToleranceDialog() {
    if (m_thread) {
        m_cancelled = true;
        m_thread->wait();
    }
}

ToleranceChoices ToleranceDialog::choices() const {
    ToleranceChoices c;
    c.optics = m_optics;
    c.optics.fields = number_list(m_fields->text().toStdString()).value_or(std::vector<double>{});
    c.optics.epd = m_epd->value();
    c.optics.stop = m_stop->value();
    c.radius = m_radius->value();
    c.thickness = m_thickness->value();
    c.air_gap = m_air_gap->value();
    c.decenter = m_decenter->value();
    c.tilt = m_tilt->value();
    c.trials = m_trials->value();
    return c;
}

void ToleranceDialog::set_choices(const ToleranceChoices& c) {
    m_optics = c.optics;
    m_fields->setText(QString::fromStdString(number_list_text(c.optics.fields)));
    m_epd->setValue(c.optics.epd);
    m_stop->setValue(c.optics.stop);
    m_radius->setValue(c.radius);
    m_thickness->setValue(c.thickness);
    m_air_gap->setValue(c.air_gap);
    m_decenter->setValue(c.decenter);
    m_tilt->setValue(c.tilt);
    m_trials->setValue(c.trials);
}

QString ToleranceDialog::status() const { return m_status->text(); }

bool ToleranceDialog::start() {
    if (running()) return false;
    const ToleranceChoices c = choices();
    if (c.optics.fields.empty()) {
        m_status->setText(tr("Fields: at least one angle in degrees, comma-separated"));
        return false;
    }
    LensDesign design;
    try {
        // The selected lens must make a system (the bench's checks and messages); the design
        // reader then takes the lenses on its axis.
        build_optical_system(m_document->scene(), m_lens);
        const QString folder =
            m_document->path().isEmpty() ? QString() : QFileInfo(m_document->path()).absolutePath();
        design = lens_design_from_json(tolerance_design_json(m_document->json(), c),
                                       folder.toStdString());
        if (tolerance_items(design).empty()) {
            throw SceneError("tolerances",
                             "no tolerance to try: give a radius, thickness, air gap, decentre "
                             "or tilt error");
        }
    } catch (const lenslab::Error& e) {
        m_status->setText(tr("Cannot tolerance: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
    m_cancelled = false;
    m_progress->setRange(0, c.trials);
    m_progress->setValue(0);
    m_status->setText(tr("Trying each error, then %1 made lenses…").arg(c.trials));
    m_run->setEnabled(false);
    m_thread = QThread::create([this, design] {
        const auto progress = [this](int done, int) {
            if (m_cancelled) throw ToleranceCancelled{};
            QMetaObject::invokeMethod(
                this, [this, done] { m_progress->setValue(done); }, Qt::QueuedConnection);
        };
        std::optional<ToleranceReport> report;
        QString error;
        try {
            report = tolerance_design(design, progress);
        } catch (const ToleranceCancelled&) {
            error = tr("Cancelled.");
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        QMetaObject::invokeMethod(
            this, [this, report, error] { on_done(report, error); }, Qt::QueuedConnection);
    });
    m_thread->setParent(this);
    m_thread->start();
    return true;
}

void ToleranceDialog::cancel() { m_cancelled = true; }

void ToleranceDialog::on_done(std::optional<ToleranceReport> report, QString error) {
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    m_run->setEnabled(true);
    if (!report) {
        m_status->setText(error);
        emit finished_run(false);
        return;
    }
    const ToleranceReport& r = *report;
    m_table->setRowCount(int(r.rows.size()));
    for (int i = 0; i < int(r.rows.size()); ++i) {
        const SensitivityRow& row = r.rows[size_t(i)];
        m_table->setItem(i, 0, new QTableWidgetItem(QString::fromStdString(row.label)));
        m_table->setItem(i, 1, new QTableWidgetItem(cell_text(row.minus)));
        m_table->setItem(i, 2, new QTableWidgetItem(cell_text(row.plus)));
    }
    const MonteCarloSummary& m = r.monte_carlo;
    const bool mm = m_document->json().value("length_unit_mm", 1.0) == 1.0;
    m_figure->set_figure(tolerance_figure(r, mm ? "mm" : ""), kToleranceFigureWidth);
    m_progress->setValue(m_progress->maximum());
    m_status->setText(
        tr("Nominal RMS spot %1 (refocused); root-sum-square of the worst changes %2.\n"
           "Monte Carlo of %3 lenses (%4 failed): mean %5, sd %6; 90% at or below %7 "
           "(the table predicted mean %8, sd %9).")
            .arg(r.nominal, 0, 'f', 5)
            .arg(r.rss_change, 0, 'f', 5)
            .arg(m.trials)
            .arg(m.failed)
            .arg(m.mean, 0, 'f', 5)
            .arg(m.sd, 0, 'f', 5)
            .arg(m.p90, 0, 'f', 5)
            .arg(r.predicted_mean, 0, 'f', 5)
            .arg(r.predicted_sd, 0, 'f', 5));
    emit finished_run(true);
}

}  // namespace lenslab::gui
