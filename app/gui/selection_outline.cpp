#include "selection_outline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lenslab::gui {

namespace {

// Widget pixels per mask cell: the outline is two pixels wide and costs a quarter of the rays.
constexpr int kOutlineCell = 2;

// The widget rectangle `shapes` cover, clipped to the image; the whole image when a corner of
// their box is behind the eye.
QRect outline_region(const std::vector<const Shape*>& shapes, const ViewCamera& view) {
    Aabb box;
    for (const Shape* s : shapes) {
        const Aabb b = s->bounds();
        box.expand(b.lo);
        box.expand(b.hi);
    }
    const QRect image = view.image().toAlignedRect();
    QRectF covered;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                     corner & 4 ? box.hi.z : box.lo.z};
        const std::optional<QPointF> at = view.project(p);
        if (!at) return image;
        covered = covered.isNull() ? QRectF(*at, QSizeF(1, 1))
                                   : covered.united(QRectF(*at, QSizeF(1, 1)));
    }
    return covered.toAlignedRect()
        .adjusted(-kOutlineCell, -kOutlineCell, kOutlineCell, kOutlineCell)
        .intersected(image);
}

}  // namespace

SelectionOutline selection_outline(const Scene& scene, int source, const ViewCamera& view,
                                   const QColor& colour) {
    std::vector<const Shape*> shapes;
    for (const SceneObject& o : scene.objects) {
        if (o.source == source && o.shape) shapes.push_back(o.shape.get());
    }
    if (shapes.empty()) return {};
    const QRect region = outline_region(shapes, view);
    const int cols = region.width() / kOutlineCell, rows = region.height() / kOutlineCell;
    if (cols < 1 || rows < 1) return {};
    std::vector<char> inside(size_t(cols) * rows, 0);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            const Ray ray = view.ray(QPointF(region.left() + (c + 0.5) * kOutlineCell,
                                             region.top() + (r + 0.5) * kOutlineCell));
            SurfaceHit hit;
            inside[size_t(r) * cols + c] =
                std::any_of(shapes.begin(), shapes.end(), [&](const Shape* s) {
                    return s->intersect(ray, 0, std::numeric_limits<double>::infinity(), hit);
                });
        }
    }
    // A cell inside with a neighbour outside (or at the region's edge) is on the outline.
    const auto in = [&](int r, int c) {
        return r >= 0 && c >= 0 && r < rows && c < cols && inside[size_t(r) * cols + c];
    };
    QImage image(cols, rows, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    bool any = false;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            if (in(r, c) && !(in(r - 1, c) && in(r + 1, c) && in(r, c - 1) && in(r, c + 1))) {
                image.setPixelColor(c, r, colour);
                any = true;
            }
        }
    }
    if (!any) return {};
    return {image, QRect(region.topLeft(), QSize(cols * kOutlineCell, rows * kOutlineCell))};
}

}  // namespace lenslab::gui
