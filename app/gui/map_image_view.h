#pragma once
// A false-colour picture (map_figure.h, detector_image.h) shown at the size of its widget,
// aspect kept: the bench dock's PSF and wavefront tabs, the detector dock's map.

#include <QImage>
#include <QLabel>

#include "image/image_io.h"

namespace lenslab::gui {

QImage to_qimage(const Image8& image);

class MapImageView : public QLabel {
    Q_OBJECT

public:
    explicit MapImageView(QWidget* parent = nullptr);
    // A null image clears the view.
    void set_image(const QImage& image);
    const QImage& image() const { return m_image; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void show_scaled();
    QImage m_image;
};

}  // namespace lenslab::gui
