#include "bench_figure_view.h"

#include <QContextMenuEvent>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QSaveFile>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/figures/diagram_canvas.h"
#include "analysis/figures/ray_diagram_image.h"
#include "analysis/figures/ray_diagram_svg.h"
#include "image/image_io.h"
#include "qpainter_canvas.h"
#include "util/file_write_error.h"

namespace lenslab::gui {

namespace {

// The CLI's minimum height of the bench's figures (analyze_command.cpp).
constexpr double kBenchFigureMinHeight = 300;
// The widget's own least size, with or without a figure.
constexpr QSize kSmallest{240, 80};
// Ctrl+wheel's zoom per notch, and its range.
constexpr double kZoomStep = 1.25, kLeastZoom = 0.2, kMostZoom = 4;

}  // namespace

BenchFigureView::BenchFigureView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(kSmallest);
    setToolTip(
        tr("Double-click: open in a window of its own; right-click: export; Ctrl+wheel: zoom"));
}

void BenchFigureView::set_figure(std::optional<RayDiagram> figure, double layout_width) {
    m_figure = std::move(figure);
    m_layout_width = layout_width;
    ask_for_room();
    update();
}

void BenchFigureView::set_least_zoom(double zoom) {
    m_least_zoom = zoom;
    ask_for_room();
    update();
}

QSizeF BenchFigureView::layout_size() const {
    if (!m_figure) return {};
    return {m_layout_width, diagram_height(*m_figure, m_layout_width, kBenchFigureMinHeight)};
}

void BenchFigureView::ask_for_room() {
    const QSizeF room = layout_size() * m_least_zoom;
    setMinimumSize(std::max(kSmallest.width(), int(std::ceil(room.width()))),
                   std::max(kSmallest.height(), int(std::ceil(room.height()))));
}

double BenchFigureView::drawn_zoom() const {
    const QSizeF size = layout_size();
    if (size.isEmpty()) return 0;
    return std::min(width() / size.width(), height() / size.height());
}

void BenchFigureView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    if (m_figure) {
        paint_bench_figure(painter, *m_figure, QRectF(rect()), m_layout_width,
                           kBenchFigureMinHeight);
    }
}

QWidget* BenchFigureView::open_window() {
    if (!m_figure) return nullptr;
    auto* window = new QWidget(this, Qt::Window);
    window->setObjectName("bench_figure_window");
    window->setAttribute(Qt::WA_DeleteOnClose);
    window->setWindowTitle(QString::fromStdString(m_figure->title));
    auto* view = new BenchFigureView(window);
    view->set_least_zoom(0);  // the window may be made smaller than the figure
    view->set_figure(m_figure, m_layout_width);
    auto* layout = new QVBoxLayout(window);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(view);
    // The command line's size, so its text is at full size (smaller screens: what fits).
    const Image8 sized = ray_diagram_image(*m_figure, m_layout_width, kBenchFigureMinHeight);
    window->resize(std::min(sized.width, 1600), std::min(sized.height, 1000));
    window->show();
    return window;
}

bool BenchFigureView::export_to(const QString& path, QString* error) const {
    if (!m_figure) {
        if (error) *error = tr("No figure to export");
        return false;
    }
    try {
        if (path.endsWith(".svg", Qt::CaseInsensitive)) {
            const std::string svg =
                ray_diagram_svg(*m_figure, m_layout_width, kBenchFigureMinHeight);
            QSaveFile out(path);
            if (!out.open(QIODevice::WriteOnly) ||
                out.write(svg.data(), qint64(svg.size())) != qint64(svg.size()) || !out.commit())
                throw FileWriteError(path.toStdString() +
                                     ": cannot write: " + out.errorString().toStdString());
        } else {
            write_png_image(ray_diagram_image(*m_figure, m_layout_width, kBenchFigureMinHeight),
                            path.toStdString());
        }
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    return true;
}

void BenchFigureView::mouseDoubleClickEvent(QMouseEvent*) { open_window(); }

void BenchFigureView::wheelEvent(QWheelEvent* event) {
    // Without Ctrl the wheel scrolls the dock's scroll area.
    if (!(event->modifiers() & Qt::ControlModifier) || !m_figure || m_least_zoom == 0) {
        event->ignore();
        return;
    }
    const double notches = event->angleDelta().y() / 120.0;
    set_least_zoom(std::clamp(drawn_zoom() * std::pow(kZoomStep, notches), kLeastZoom, kMostZoom));
    event->accept();
}

void BenchFigureView::contextMenuEvent(QContextMenuEvent* event) {
    if (!m_figure) return;
    QMenu menu(this);
    menu.addAction(tr("Open in a window"), this, [this] { open_window(); });
    menu.addAction(tr("Export..."), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export figure"), QString(),
                                                          tr("SVG (*.svg);;PNG (*.png)"));
        QString error;
        if (!path.isEmpty() && !export_to(path, &error))
            QMessageBox::warning(this, tr("Cannot export"), error);
    });
    menu.exec(event->globalPos());
}

}  // namespace lenslab::gui
