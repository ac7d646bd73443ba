#include "map_image_view.h"

#include <QPixmap>
#include <algorithm>

namespace lenslab::gui {

QImage to_qimage(const Image8& image) {
    QImage out(image.width, image.height, QImage::Format_RGB888);
    for (int y = 0; y < image.height; ++y) {
        std::copy_n(image.rgb.data() + size_t(y) * image.width * 3, image.width * 3,
                    out.scanLine(y));
    }
    return out;
}

MapImageView::MapImageView(QWidget* parent) : QLabel(parent) {
    setAlignment(Qt::AlignCenter);
    setMinimumSize(160, 120);
    // Ignored: the picture follows the widget's size instead of setting it.
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
}

void MapImageView::set_image(const QImage& image) {
    m_image = image;
    if (m_image.isNull()) {
        clear();
        return;
    }
    show_scaled();
}

void MapImageView::resizeEvent(QResizeEvent* event) {
    QLabel::resizeEvent(event);
    if (!m_image.isNull()) show_scaled();
}

void MapImageView::show_scaled() {
    setPixmap(QPixmap::fromImage(m_image).scaled(size().expandedTo(QSize(160, 120)),
                                                 Qt::KeepAspectRatio, Qt::SmoothTransformation));
}

}  // namespace lenslab::gui
