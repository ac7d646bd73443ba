#include "optimise_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QThread>
#include <QVBoxLayout>

#include "bench_figures.h"
#include "optimize/lens_design.h"
#include "optimize/optimize_design.h"
#include "scene_document.h"
#include "util/error.h"

namespace lenslab::gui {

namespace {

// Thrown from the optimiser's progress callback to end the run early.
struct OptimiseCancelled {};

}  // namespace

OptimiseDialog::OptimiseDialog(SceneDocument* document, int lens, QWidget* parent)
    : QDialog(parent),
      m_document(document),
      m_lens(lens),
      m_efl(new QDoubleSpinBox(this)),
      m_fields(new QLineEdit(this)),
      m_wavelengths(new QLineEdit(this)),
      m_epd(new QDoubleSpinBox(this)),
      m_stop(new QSpinBox(this)),
      m_curvatures(new QCheckBox(tr("Curvatures (both faces of each lens)"), this)),
      m_gaps(new QCheckBox(tr("Air gaps between the lenses"), this)),
      m_model_glasses(
          new QCheckBox(tr("Model glasses (n_d, V_d of a lens written with one)"), this)),
      m_substitute(new QCheckBox(tr("Then the nearest catalogue glasses"), this)),
      m_iterations(new QSpinBox(this)),
      m_global_starts(new QSpinBox(this)),
      m_progress(new QProgressBar(this)),
      m_status(new QLabel(this)),
      m_run(new QPushButton(tr("Optimise"), this)),
      m_cancel(new QPushButton(tr("Cancel"), this)) {
    setObjectName("optimise_dialog");
    setWindowTitle(tr("Optimise lenses"));
    m_efl->setRange(-1e6, 1e6);
    m_efl->setDecimals(3);
    m_epd->setRange(1e-3, 1e6);
    m_epd->setDecimals(3);
    m_stop->setRange(1, 999);
    m_iterations->setRange(0, 100000);
    m_global_starts->setObjectName("global_starts");
    m_global_starts->setRange(0, 1000);
    m_global_starts->setSpecialValueText(tr("off (from the lenses as they are)"));
    m_global_starts->setToolTip(
        tr("Start the optimiser from this many designs spread over the curvatures' range and "
           "keep the best (docs/optimizer.md, Global search)"));
    m_wavelengths->setPlaceholderText(tr("F, d, C lines"));
    m_status->setWordWrap(true);
    auto* form = new QFormLayout;
    form->addRow(tr("EFL target"), m_efl);
    form->addRow(tr("Fields (deg)"), m_fields);
    form->addRow(tr("Wavelengths (nm)"), m_wavelengths);
    form->addRow(tr("Entrance pupil diameter"), m_epd);
    form->addRow(tr("Stop surface"), m_stop);
    form->addRow(tr("Vary"), m_curvatures);
    form->addRow(QString(), m_gaps);
    form->addRow(QString(), m_model_glasses);
    form->addRow(QString(), m_substitute);
    m_model_glasses->setObjectName("vary_model_glasses");
    m_substitute->setObjectName("substitute_glasses");
    m_substitute->setToolTip(
        tr("After the optimisation, each model glass is replaced by the "
           "nearest catalogue glasses in turn, the lenses re-optimised, the "
           "best kept (docs/optimizer.md, Model glasses and substitution)"));
    form->addRow(tr("Iterations"), m_iterations);
    form->addRow(tr("Global search starts"), m_global_starts);
    auto* buttons = new QDialogButtonBox(this);
    buttons->addButton(m_run, QDialogButtonBox::AcceptRole);
    buttons->addButton(m_cancel, QDialogButtonBox::RejectRole);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(buttons);
    connect(m_run, &QPushButton::clicked, this, &OptimiseDialog::start);
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        if (running()) {
            cancel();
        } else {
            reject();
        }
    });
    set_choices(OptimiseChoices{});
}

OptimiseDialog::~OptimiseDialog() {
    if (m_thread) {
        m_cancelled = true;
        m_thread->wait();
    }
}

OptimiseChoices OptimiseDialog::choices() const {
    OptimiseChoices c;
    c.efl_target = m_efl->value();
    c.fields = number_list(m_fields->text().toStdString()).value_or(std::vector<double>{});
    c.wavelengths =
        number_list(m_wavelengths->text().toStdString()).value_or(std::vector<double>{});
    c.epd = m_epd->value();
    c.stop = m_stop->value();
    c.vary_curvatures = m_curvatures->isChecked();
    c.vary_air_gaps = m_gaps->isChecked();
    c.vary_model_glasses = m_model_glasses->isChecked();
    c.substitute_glasses = m_substitute->isChecked();
    c.iterations = m_iterations->value();
    c.global_starts = m_global_starts->value();
    return c;
}

void OptimiseDialog::set_choices(const OptimiseChoices& c) {
    m_efl->setValue(c.efl_target);
    m_fields->setText(QString::fromStdString(number_list_text(c.fields)));
    m_wavelengths->setText(QString::fromStdString(number_list_text(c.wavelengths)));
    m_epd->setValue(c.epd);
    m_stop->setValue(c.stop);
    m_curvatures->setChecked(c.vary_curvatures);
    m_gaps->setChecked(c.vary_air_gaps);
    m_model_glasses->setChecked(c.vary_model_glasses);
    m_substitute->setChecked(c.substitute_glasses);
    m_iterations->setValue(c.iterations);
    m_global_starts->setValue(c.global_starts);
}

QString OptimiseDialog::status() const { return m_status->text(); }

bool OptimiseDialog::start() {
    if (running()) return false;
    const OptimiseChoices c = choices();
    if (c.fields.empty()) {
        m_status->setText(tr("Fields: at least one angle in degrees, comma-separated"));
        return false;
    }
    LensDesign design;
    try {
        const OpticalSystem system = build_optical_system(m_document->scene(), m_lens);
        const QString folder =
            m_document->path().isEmpty() ? QString() : QFileInfo(m_document->path()).absolutePath();
        design = lens_design_from_json(optimise_design_json(m_document->json(), system, c),
                                       folder.toStdString());
    } catch (const lenslab::Error& e) {
        m_status->setText(tr("Cannot optimise: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
    m_cancelled = false;
    // A global search reports runs ended (its starts, then the few polished), not iterations.
    const bool global = design.global_search.starts > 0;
    const int runs = global_search_runs(design.global_search);
    m_progress->setRange(0, std::max(1, global ? runs : c.iterations));
    m_progress->setValue(0);
    m_status->setText(tr("Optimising…"));
    m_run->setEnabled(false);
    m_thread = QThread::create([this, design, global, runs] {
        const auto progress = [this, global, runs](const LmProgress& p) {
            if (m_cancelled) throw OptimiseCancelled{};
            QMetaObject::invokeMethod(
                this,
                [this, p, global, runs] {
                    m_progress->setValue(p.iteration);
                    m_status->setText(
                        global ? tr("Global search: %1 of %2 runs, best merit %3")
                                     .arg(p.iteration)
                                     .arg(runs)
                                     .arg(p.merit)
                               : tr("Iteration %1: merit %2").arg(p.iteration).arg(p.merit));
                },
                Qt::QueuedConnection);
        };
        std::optional<nlohmann::json> scene;
        QString error;
        try {
            scene = nlohmann::json(optimize_design(design, -1, progress).scene);
        } catch (const OptimiseCancelled&) {
            error = tr("Cancelled: the lenses are unchanged.");
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        QMetaObject::invokeMethod(
            this, [this, scene, error] { on_done(scene, error); }, Qt::QueuedConnection);
    });
    m_thread->setParent(this);
    m_thread->start();
    return true;
}

void OptimiseDialog::cancel() { m_cancelled = true; }

void OptimiseDialog::on_done(std::optional<nlohmann::json> scene, QString error) {
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    m_run->setEnabled(true);
    bool applied = false;
    if (scene) {
        applied = m_document->apply(*scene, tr("Optimise lenses"), &error);
        if (applied) {
            m_progress->setValue(m_progress->maximum());
            m_status->setText(tr("Done: Ctrl+Z restores the lenses."));
        }
    }
    if (!applied) m_status->setText(error);
    emit finished_run(applied);
}

}  // namespace lenslab::gui
