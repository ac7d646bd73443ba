#pragma once
// Shows the progressive render and turns the mouse into camera moves and selections:
// left drag orbits about the point looked at, right or middle drag pans, the wheel zooms,
// a click selects the object under the cursor.

#include <QImage>
#include <QPoint>
#include <QWidget>
#include <nlohmann/json.hpp>

namespace lenslab::gui {

class SceneDocument;

class Viewport : public QWidget {
    Q_OBJECT

public:
    Viewport(SceneDocument* document, QWidget* parent = nullptr);

    void set_image(const QImage& image);
    const QImage& image() const { return m_image; }

    // The object whose surface is under a widget position, or -1.
    int pick(const QPoint& pos) const;

signals:
    void object_picked(int object);
    void edit_refused(const QString& message);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    QRect image_rect() const;  // where the image is drawn, aspect kept

    SceneDocument* m_document;
    QImage m_image;
    QPoint m_press, m_last;
    Qt::MouseButton m_button = Qt::NoButton;
    bool m_dragged = false;
    nlohmann::json m_before;  // the document when the drag started
};

}  // namespace lenslab::gui
