#include "bench_figure_view.h"

#include "qpainter_canvas.h"

namespace lenslab::gui {

namespace {

// The CLI's minimum height of the bench's figures (analyze_command.cpp).
constexpr double kBenchFigureMinHeight = 300;

}  // namespace

BenchFigureView::BenchFigureView(QWidget* parent) : QWidget(parent) { setMinimumSize(320, 200); }

void BenchFigureView::set_figure(std::optional<RayDiagram> figure, double layout_width) {
    m_figure = std::move(figure);
    m_layout_width = layout_width;
    update();
}

void BenchFigureView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    if (m_figure) {
        paint_bench_figure(painter, *m_figure, QRectF(rect()), m_layout_width,
                           kBenchFigureMinHeight);
    }
}

}  // namespace lenslab::gui
