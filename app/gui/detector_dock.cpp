#include "detector_dock.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QPixmap>
#include <QScrollArea>
#include <QVBoxLayout>
#include <algorithm>

#include "analysis/detectors/detector_files.h"
#include "analysis/detectors/detector_image.h"
#include "json_pointer.h"
#include "map_image_view.h"
#include "scene_document.h"

namespace lenslab::gui {

DetectorDock::DetectorDock(SceneDocument* document, QWidget* parent)
    : QDockWidget(tr("Detector"), parent),
      m_document(document),
      m_title(new QLabel(this)),
      m_picture(new QLabel(this)),
      m_summary(new QLabel(this)),
      m_photons(new QSpinBox(this)),
      m_log(new QCheckBox(tr("log scale"), this)),
      m_measure(new QPushButton(tr("Measure"), this)) {
    setObjectName("detector_dock");
    auto* body = new QWidget(this);
    auto* v = new QVBoxLayout(body);
    auto* controls = new QHBoxLayout;
    m_photons->setObjectName("detector_photons");
    m_photons->setRange(1000, 100000000);
    m_photons->setSingleStep(100000);
    m_photons->setSuffix(tr(" photons/light"));
    m_measure->setObjectName("detector_measure");
    m_log->setObjectName("detector_log");
    // Two rows, so the dock stays narrow enough for a small or scaled screen.
    controls->addWidget(m_log);
    controls->addStretch(1);
    controls->addWidget(m_measure);
    m_title->setObjectName("detector_title");
    m_title->setWordWrap(true);
    m_picture->setObjectName("detector_picture");
    m_picture->setAlignment(Qt::AlignCenter);
    m_picture->setMinimumSize(160, 60);
    m_picture->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    m_picture->setScaledContents(false);
    m_summary->setObjectName("detector_summary");
    m_summary->setWordWrap(true);
    m_summary->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    v->addWidget(m_photons);
    v->addLayout(controls);
    v->addWidget(m_title);
    v->addWidget(m_picture, 1);
    // The figures (a line per band, per detector) scroll instead of growing the dock past
    // the window.
    auto* summary_scroll = new QScrollArea(body);
    summary_scroll->setObjectName("detector_summary_scroll");
    summary_scroll->setWidget(m_summary);
    summary_scroll->setWidgetResizable(true);
    summary_scroll->setFrameShape(QFrame::NoFrame);
    v->addWidget(summary_scroll);
    setWidget(body);

    connect(m_measure, &QPushButton::clicked, this, &DetectorDock::measure);
    connect(m_log, &QCheckBox::toggled, this, &DetectorDock::refresh);
    connect(document, &SceneDocument::changed, this, [this] {
        // An edit makes the last measurement stale; the photon count follows the scene.
        stop_worker();
        m_result.reset();
        m_photons->setValue(static_cast<int>(
            std::min<int64_t>(m_document->scene().render.photons, m_photons->maximum())));
        refresh();
    });
    m_photons->setValue(static_cast<int>(
        std::min<int64_t>(m_document->scene().render.photons, m_photons->maximum())));
    refresh();
}

DetectorDock::~DetectorDock() { stop_worker(); }

void DetectorDock::stop_worker() {
    ++m_generation;  // whatever the worker still sends is stale
    if (!m_worker.joinable()) return;
    m_control->cancel();
    m_worker.join();
    m_measure->setText(tr("Measure"));
}

void DetectorDock::show_pointer(const QString& pointer) {
    const QStringList tokens = split_pointer(pointer);
    if (tokens.size() != 2 || tokens[0] != "objects") return;
    const int entry = tokens[1].toInt();
    const Scene& scene = m_document->scene();
    // Scene objects follow the file's entries, except that a lens group makes several.
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (scene.objects[i].source == entry && scene.objects[i].detector) {
            m_object = int(i);
            refresh();
            return;
        }
    }
}

const DetectorMeasurement* DetectorDock::shown_measurement() const {
    if (!m_result) return nullptr;
    for (const DetectorMeasurement& m : m_result->detectors) {
        if (m.object == m_object) return &m;
    }
    return nullptr;
}

void DetectorDock::measure() {
    if (m_worker.joinable()) {  // the button reads "Stop" while measuring
        stop_worker();
        refresh();
        return;
    }
    if (detector_objects(m_document->scene()).empty()) return;
    DetectionSettings settings;
    settings.photons_per_light = m_photons->value();
    settings.caustic_photons_per_light = m_document->scene().render.caustic_photons;
    settings.aim = m_document->scene().render.aim_photons;
    settings.seed = m_document->scene().render.seed;
    settings.max_depth = m_document->scene().render.max_depth;
    m_control = std::make_unique<RenderControl>();
    m_measure->setText(tr("Stop"));
    m_summary->setText(tr("measuring..."));
    // The worker reads its own copy of the scene; the result comes back queued to this
    // object (dropped if the dock is gone; the destructor joins first).
    const int generation = ++m_generation;
    m_worker = std::thread(
        [this, scene = m_document->scene(), settings, control = m_control.get(), generation] {
            // An exception must not leave the thread (it would end the program): it is shown
            // in the dock instead (out of memory for the photons, a bug).
            std::shared_ptr<DetectionResult> result;
            std::string error;
            try {
                result =
                    std::make_shared<DetectionResult>(measure_detectors(scene, settings, *control));
            } catch (const std::exception& e) {
                error = e.what();
            } catch (...) {
                error = "unknown error";
            }
            QMetaObject::invokeMethod(
                this, [this, result, error, generation] { finish(result, error, generation); },
                Qt::QueuedConnection);
        });
}

void DetectorDock::finish(std::shared_ptr<DetectionResult> result, const std::string& error,
                          int generation) {
    if (generation != m_generation) return;  // stopped or superseded: already joined
    if (m_worker.joinable()) m_worker.join();
    m_measure->setText(tr("Measure"));
    if (!result) {
        m_result.reset();
        refresh();
        m_summary->setText(tr("Measuring failed: %1").arg(QString::fromStdString(error)));
        return;
    }
    if (result->cancelled) {
        refresh();
        return;
    }
    m_result = std::move(result);
    refresh();
    emit measured();
}

void DetectorDock::refresh() {
    const Scene& scene = m_document->scene();
    const std::vector<int> detectors = detector_objects(scene);
    if (std::find(detectors.begin(), detectors.end(), m_object) == detectors.end()) {
        m_object = detectors.empty() ? -1 : detectors.front();
    }
    m_measure->setEnabled(!detectors.empty());
    if (m_object < 0) {
        m_title->setText(
            tr("No detector in this scene: mark a triangle, disc or rectangle as a detector."));
        m_image = QImage();
        m_picture->clear();
        m_summary->clear();
        return;
    }
    m_title->setText(
        tr("<b>%1</b>")
            .arg(QString::fromStdString(scene.objects[size_t(m_object)].name).toHtmlEscaped()));
    const DetectorMeasurement* m = shown_measurement();
    if (!m) {
        m_image = QImage();
        m_picture->clear();
        if (!m_worker.joinable())
            m_summary->setText(tr("Press Measure to trace photons onto the detectors."));
        return;
    }
    m_image =
        to_qimage(detector_image(*m, m_log->isChecked() ? ColourScale::Log : ColourScale::Linear));
    show_image();
    m_summary->setText(QString::fromStdString(detector_summary_text(*m)).trimmed());
}

void DetectorDock::show_image() {
    if (m_image.isNull()) return;
    m_picture->setPixmap(
        QPixmap::fromImage(m_image).scaled(m_picture->size().expandedTo(QSize(160, 120)),
                                           Qt::KeepAspectRatio, Qt::SmoothTransformation));
}

void DetectorDock::resizeEvent(QResizeEvent* event) {
    QDockWidget::resizeEvent(event);
    show_image();
}

}  // namespace lenslab::gui
