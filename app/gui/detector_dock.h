#pragma once
// The detector dock: the irradiance map of a detector (a triangle, disc or rectangle marked
// `detector`), measured on request ("Measure") on a worker thread, with its total power,
// peak and centroid. It follows the selection: picking a detector in the scene tree shows
// that one. The picture is the one `lenslab detect` writes as <name>.png.

#include <QCheckBox>
#include <QDockWidget>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "analysis/detectors/detector.h"

namespace lenslab::gui {

class SceneDocument;

class DetectorDock : public QDockWidget {
    Q_OBJECT

public:
    explicit DetectorDock(SceneDocument* document, QWidget* parent = nullptr);
    ~DetectorDock() override;

    // Shows the detector at `pointer` ("/objects/3") when it is one; anything else keeps
    // the detector shown.
    void show_pointer(const QString& pointer);
    // Starts a measurement of every detector in the scene (or stops the one running).
    void measure();
    bool is_measuring() const { return m_worker.joinable(); }

    // What is shown, for tests: the object index of the detector, its measurement if there
    // is a current one, the picture and the summary.
    int shown_object() const { return m_object; }
    const DetectorMeasurement* shown_measurement() const;
    const QLabel* picture() const { return m_picture; }
    QString summary_text() const { return m_summary->text(); }
    QSpinBox* photons_box() const { return m_photons; }

signals:
    void measured();  // a measurement finished and is shown

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void refresh();
    void show_image();
    // `result` is null when measuring threw; `error` then says why.
    void finish(std::shared_ptr<DetectionResult> result, const std::string& error, int generation);
    void stop_worker();

    SceneDocument* m_document;
    QLabel* m_title;
    QLabel* m_picture;
    QLabel* m_summary;
    QSpinBox* m_photons;
    QCheckBox* m_log;
    QPushButton* m_measure;

    int m_object = -1;                          // the detector shown (index in objects)
    std::shared_ptr<DetectionResult> m_result;  // the last measurement, of the scene as it is
    QImage m_image;                             // its picture, unscaled
    int m_generation = 0;  // a measurement's result counts only if still current
    std::thread m_worker;
    std::unique_ptr<RenderControl> m_control;
};

}  // namespace lenslab::gui
