#pragma once
// Edit ▸ Tolerance lenses…: how much the lenses on the selected lens's axis degrade as a
// workshop makes them (docs/optimizer.md#tolerancing): ± errors of every radius, thickness and
// air gap, each lens's decentre and tilt, the sensitivity table and a Monte Carlo run in a
// background thread, with a progress bar and Cancel. The document is not changed.

#include <QDialog>
#include <atomic>
#include <optional>

#include "optimise_design_json.h"
#include "optimize/tolerance.h"

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;
class QThread;

namespace lenslab::gui {

class BenchFigureView;
class SceneDocument;

// What the dialog asks: the optical choices the Optimise dialog asks (fields, wavelengths,
// pupil, stop) and the tolerances block.
struct ToleranceChoices {
    OptimiseChoices optics;
    double radius = 0.05, thickness = 0.05, air_gap = 0.05;  // ± mm
    double decenter = 0, tilt = 0;                           // ± mm, ± degrees
    int trials = 200;
};

// The design file `lenslab tolerance` would read for these choices: the scene inline, its
// `tolerances` block from the choices.
nlohmann::json tolerance_design_json(const nlohmann::json& scene, const ToleranceChoices& c);

class ToleranceDialog : public QDialog {
    Q_OBJECT

public:
    // `lens`: the scene object (index into Scene::objects) whose axis is toleranced.
    ToleranceDialog(SceneDocument* document, int lens, QWidget* parent = nullptr);
    ~ToleranceDialog() override;

    ToleranceChoices choices() const;
    void set_choices(const ToleranceChoices& choices);
    // Starts the run; false (and why in status()) when the design is not usable.
    bool start();
    void cancel();
    bool running() const { return m_thread != nullptr; }
    QString status() const;
    QTableWidget* table() const { return m_table; }
    BenchFigureView* figure() const { return m_figure; }
    QProgressBar* progress() const { return m_progress; }

signals:
    // The run ended: the table filled, or cancelled or failed (status() says).
    void finished_run(bool done);

private:
    void on_done(std::optional<ToleranceReport> report, QString error);

    SceneDocument* m_document;
    int m_lens;
    OptimiseChoices m_optics;  // the optical choices, from the ray diagram's defaults
    QLineEdit* m_fields;
    QDoubleSpinBox* m_epd;
    QSpinBox* m_stop;
    QDoubleSpinBox* m_radius;
    QDoubleSpinBox* m_thickness;
    QDoubleSpinBox* m_air_gap;
    QDoubleSpinBox* m_decenter;
    QDoubleSpinBox* m_tilt;
    QSpinBox* m_trials;
    QProgressBar* m_progress;
    QLabel* m_status;
    QTableWidget* m_table;
    BenchFigureView* m_figure;  // the Monte Carlo's histogram and yield
    QPushButton* m_run;
    QPushButton* m_close;
    QThread* m_thread = nullptr;
    std::atomic<bool> m_cancelled{false};
};

}  // namespace lenslab::gui
