#pragma once
// A widget showing one figure of the bench (spot diagrams, fans, curves, MTF), drawn by the
// library's layout through a QPainter canvas (qpainter_canvas.h). In the dock it is never
// drawn below a zoom at which its text reads (kReadableZoom of the command line's size; the
// dock scrolls it, Ctrl+wheel zooms); a double-click opens it in a window of its own at the
// command line's size, and the context menu exports it as the command line writes it (SVG
// or PNG).

#include <QWidget>
#include <optional>

#include "analysis/figures/ray_diagram.h"

namespace lenslab::gui {

class BenchFigureView : public QWidget {
    Q_OBJECT

public:
    // The least zoom the dock draws a figure at: its 12-pixel labels about 10 pixels high.
    static constexpr double kReadableZoom = 0.8;

    explicit BenchFigureView(QWidget* parent = nullptr);
    // `layout_width`: the picture's width as the CLI lays it out (field_figure_width).
    void set_figure(std::optional<RayDiagram> figure, double layout_width = 600);
    const std::optional<RayDiagram>& figure() const { return m_figure; }

    // The least zoom the figure is drawn at (the widget asks for that much room; a larger
    // widget draws it larger); 0: fitted to the widget whatever its size.
    void set_least_zoom(double zoom);
    double least_zoom() const { return m_least_zoom; }
    // The zoom the figure is drawn at now (1: the command line's size).
    double drawn_zoom() const;

    // The figure in a window of its own (objectName "bench_figure_window"), or nullptr when
    // there is none to show.
    QWidget* open_window();
    // Writes the figure as `path`'s suffix says (.svg, else PNG); false with `error` set.
    bool export_to(const QString& path, QString* error) const;

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

private:
    // The command line's picture size of the figure.
    QSizeF layout_size() const;
    void ask_for_room();

    std::optional<RayDiagram> m_figure;
    double m_layout_width = 600;
    double m_least_zoom = kReadableZoom;
};

}  // namespace lenslab::gui
