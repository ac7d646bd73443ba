#pragma once
// The bench dock: the optical bench of the selected lens in tabs. Layout: the lens system on
// its axis, drawn from the same diagram model as `lenslab analyze --svg`, with its EFL and
// BFL; Spots, Fans, Field curves and MTF: the figures of `lenslab analyze --spots-svg` and
// the rest (bench_figures.h), for the fields, wavelengths, EPD and stop of the controls. It
// follows the selection and redraws whenever the scene changes; the figures after a short
// pause, and only while one of their tabs is shown.

#include <QDockWidget>
#include <QLabel>
#include <optional>

#include "analysis/figures/ray_diagram.h"
#include "bench_figures.h"
#include "optimise_design_json.h"

class QDoubleSpinBox;
class QLineEdit;
class QComboBox;
class QSpinBox;
class QTabWidget;
class QTimer;

namespace lenslab::gui {

class SceneDocument;

// Paints a RayDiagram with QPainter, scaled to fit (true aspect).
class RayDiagramView : public QWidget {
    Q_OBJECT

public:
    explicit RayDiagramView(QWidget* parent = nullptr);
    void set_diagram(std::optional<RayDiagram> diagram);
    const std::optional<RayDiagram>& diagram() const { return m_diagram; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::optional<RayDiagram> m_diagram;
};

class BenchFigureView;
class MapImageView;

class RayDiagramDock : public QDockWidget {
    Q_OBJECT

public:
    RayDiagramDock(SceneDocument* document, QWidget* parent = nullptr);

    // Follows the editor's selection (a JSON pointer such as "/objects/2").
    void show_pointer(const QString& pointer);

    bool has_diagram() const { return m_view->diagram().has_value(); }
    RayDiagramView* view() const { return m_view; }
    // What the dock says above the picture: the figures, or why there is no diagram.
    QString message() const { return m_message->text(); }

    QTabWidget* tabs() const { return m_tabs; }
    // The figures last computed, and the settings they were computed with.
    const BenchFigures& bench() const { return m_bench; }
    const BenchSettings& settings() const { return m_settings; }
    // The spot tab's numbers: per field the polychromatic RMS and Airy radii, per wavelength
    // the RMS and geometric radii.
    QString spot_numbers() const { return m_spot_numbers->text(); }
    BenchFigureView* spot_view() const { return m_spot_view; }
    MapImageView* psf_view() const { return m_psf_view; }
    MapImageView* wavefront_view() const { return m_wavefront_view; }
    QLineEdit* fields_edit() const { return m_fields; }
    QLineEdit* wavelengths_edit() const { return m_wavelengths; }
    // Recomputes the bench figures now instead of after the pause.
    void update_bench();
    // The scene object of the selected lens (index into Scene::objects); -1: none.
    int lens() const { return m_lens; }
    // What the Optimise dialog starts from: the lens's EFL and entrance pupil, the dock's
    // fields, wavelengths and stop.
    OptimiseChoices optimise_defaults() const;

private:
    void refresh();
    QWidget* make_controls();
    void schedule_bench();
    bool read_settings(QString& error);
    void show_bench();

    SceneDocument* m_document;
    QString m_pointer;
    int m_lens = -1;  // the scene object of the selected lens; -1: none
    RayDiagramView* m_view;
    QLabel* m_message;
    QTabWidget* m_tabs;
    QLineEdit* m_fields;
    QLineEdit* m_wavelengths;
    QDoubleSpinBox* m_epd;
    QSpinBox* m_stop;
    QComboBox* m_ray_aiming;
    QLabel* m_spot_numbers;
    BenchFigureView* m_spot_view;
    BenchFigureView* m_fan_view;
    BenchFigureView* m_curve_view;
    BenchFigureView* m_mtf_view;
    MapImageView* m_psf_view;
    MapImageView* m_wavefront_view;
    QTimer* m_bench_timer;
    BenchSettings m_settings;
    BenchFigures m_bench;
    bool m_bench_stale = true;
    double m_efl = 100, m_pupil = 10;  // of the lens last drawn
};

}  // namespace lenslab::gui
