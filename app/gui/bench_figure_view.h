#pragma once
// A widget showing one figure of the bench (spot diagrams, fans, curves, MTF), drawn by the
// library's layout through a QPainter canvas (qpainter_canvas.h).

#include <QWidget>
#include <optional>

#include "analysis/figures/ray_diagram.h"

namespace lenslab::gui {

class BenchFigureView : public QWidget {
    Q_OBJECT

public:
    explicit BenchFigureView(QWidget* parent = nullptr);
    // `layout_width`: the picture's width as the CLI lays it out (field_figure_width).
    void set_figure(std::optional<RayDiagram> figure, double layout_width = 600);
    const std::optional<RayDiagram>& figure() const { return m_figure; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::optional<RayDiagram> m_figure;
    double m_layout_width = 600;
};

}  // namespace lenslab::gui
