#pragma once
// A widget showing one figure of the bench (spot diagrams, fans, curves, MTF), drawn by the
// library's layout through a QPainter canvas (qpainter_canvas.h). The dock shows it small:
// a double-click opens it in a window of its own at the size the command line lays it out
// (its text at full size, the window free to resize), and the context menu exports it as the
// command line writes it (SVG or PNG).

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

    // The figure in a window of its own (objectName "bench_figure_window"), or nullptr when
    // there is none to show.
    QWidget* open_window();
    // Writes the figure as `path`'s suffix says (.svg, else PNG); false with `error` set.
    bool export_to(const QString& path, QString* error) const;

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

private:
    std::optional<RayDiagram> m_figure;
    double m_layout_width = 600;
};

}  // namespace lenslab::gui
