#pragma once
// Edit ▸ Optimise…: optimises the lenses on the selected lens's axis (docs/optimizer.md) in a
// background thread, with a progress bar and Cancel, and applies the result to the document
// as one undoable edit.

#include <QDialog>
#include <atomic>
#include <optional>

#include "optimise_design_json.h"

class QCheckBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QThread;

namespace lenslab::gui {

class SceneDocument;

class OptimiseDialog : public QDialog {
    Q_OBJECT

public:
    // `lens`: the scene object (index into Scene::objects) whose axis is optimised.
    OptimiseDialog(SceneDocument* document, int lens, QWidget* parent = nullptr);
    ~OptimiseDialog() override;

    OptimiseChoices choices() const;
    void set_choices(const OptimiseChoices& choices);
    // Starts the optimiser; false (and why in status()) when the design is not usable.
    bool start();
    void cancel();
    bool running() const { return m_thread != nullptr; }
    QString status() const;
    QProgressBar* progress() const { return m_progress; }

signals:
    // The run ended: applied (one undoable edit), cancelled, or failed (status() says).
    void finished_run(bool applied);

private:
    void on_done(std::optional<nlohmann::json> scene, QString error);

    SceneDocument* m_document;
    int m_lens;
    QDoubleSpinBox* m_efl;
    QLineEdit* m_fields;
    QLineEdit* m_wavelengths;
    QDoubleSpinBox* m_epd;
    QSpinBox* m_stop;
    QCheckBox* m_curvatures;
    QCheckBox* m_gaps;
    QCheckBox* m_model_glasses;
    QCheckBox* m_substitute;
    QSpinBox* m_iterations;
    QSpinBox* m_global_starts;
    QProgressBar* m_progress;
    QLabel* m_status;
    QPushButton* m_run;
    QPushButton* m_cancel;
    QThread* m_thread = nullptr;
    std::atomic<bool> m_cancelled{false};
};

}  // namespace lenslab::gui
