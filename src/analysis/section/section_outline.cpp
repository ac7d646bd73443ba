#include "analysis/section/section_outline.h"

#include <array>
#include <cmath>
#include <unordered_map>

#include "geometry/lens/lens_solid.h"

namespace lenslab {

namespace {

// Where a flat convex polygon cuts the plane: one segment, or nothing.
void section_cut_polygon(const Vec3* corners, int count, const SectionPlane& plane,
                         std::vector<SectionCurve>& out) {
    SectionCurve cut;
    for (int i = 0; i < count; ++i) {
        const Vec3& p = corners[i];
        const Vec3& q = corners[(i + 1) % count];
        const double dp = plane.distance(p), dq = plane.distance(q);
        if (dp == 0) cut.points.push_back(plane.of(p));
        if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0))
            cut.points.push_back(plane.of(p + (q - p) * (dp / (dp - dq))));
    }
    if (cut.points.size() >= 2) {
        cut.points.resize(2);
        out.push_back(std::move(cut));
    }
}

// The chord a disc cuts from the plane.
void section_cut_disc(const FlatPatch& disc, const SectionPlane& plane,
                      std::vector<SectionCurve>& out) {
    const Vec3 n = plane.normal(), normal = disc.frame.n, centre = disc.frame.origin;
    const Vec3 along = cross(normal, n);  // the chord's direction
    if (length(along) < 1e-12) return;    // parallel planes
    // Towards the plane, within the disc's plane.
    const Vec3 across = normalize(n - normal * dot(n, normal));
    const double s = -plane.distance(centre) / dot(across, n);
    const double half = disc.radius * disc.radius - s * s;
    if (half <= 0) return;
    const Vec3 mid = centre + across * s;
    const Vec3 d = normalize(along) * std::sqrt(half);
    out.push_back({{plane.of(mid - d), plane.of(mid + d)}, false});
}

bool section_holds_lens_axis(const LensPrescription& p, const SectionPlane& plane) {
    const double tolerance = 1e-9 * std::max(1.0, p.diameter);
    return std::abs(dot(p.axis, plane.normal())) < 1e-9 &&
           std::abs(plane.distance(p.centre)) < tolerance;
}

// Marching squares over `shape.contains` on a grid of plane points, each crossing of a
// grid edge bisected onto the surface, the cells' segments chained into curves.
class SolidContour {
public:
    SolidContour(const Shape& shape, const SectionPlane& plane, int grid)
        : m_shape(shape), m_plane(plane), m_n(grid) {}

    void run(std::vector<SectionCurve>& out) {
        const BoundingSphere sphere = m_shape.bounding_sphere();
        const double d = m_plane.distance(sphere.centre);
        if (std::abs(d) >= sphere.radius) return;
        // The section lies in this disc; a margin keeps the grid's border outside.
        const double half = 1.02 * std::sqrt(sphere.radius * sphere.radius - d * d);
        const DiagramPoint c = m_plane.of(sphere.centre);
        m_a0 = c.z - half;
        m_b0 = c.y - half;
        m_step = 2 * half / m_n;
        const int nodes = m_n + 1;
        m_inside.assign(size_t(nodes) * nodes, 0);
        for (int j = 0; j < nodes; ++j) {
            for (int i = 0; i < nodes; ++i) m_inside[j * nodes + i] = inside(node(i, j));
        }
        for (int j = 0; j < m_n; ++j) {
            for (int i = 0; i < m_n; ++i) cell(i, j);
        }
        chain(out);
    }

private:
    DiagramPoint node(int i, int j) const { return {m_a0 + i * m_step, m_b0 + j * m_step}; }
    bool inside(const DiagramPoint& p) const { return m_shape.contains(m_plane.at(p)); }
    bool inside(int i, int j) const { return m_inside[j * (m_n + 1) + i] != 0; }

    // Edge ids: 2 * node + 0 for the edge from node (i, j) to (i + 1, j), + 1 to (i, j + 1).
    long edge_id(int i, int j, int side) const {
        switch (side) {
            case 0:
                return 2L * (j * (m_n + 1) + i);  // bottom
            case 1:
                return 2L * (j * (m_n + 1) + i + 1) + 1;  // right
            case 2:
                return 2L * ((j + 1) * (m_n + 1) + i);  // top
            default:
                return 2L * (j * (m_n + 1) + i) + 1;  // left
        }
    }

    // The surface point on a cell side, by bisection between its inside and outside ends.
    DiagramPoint crossing(int i, int j, int side) const {
        static constexpr int kEnds[4][2][2] = {
            {{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{0, 1}, {1, 1}}, {{0, 0}, {0, 1}}};
        DiagramPoint in = node(i + kEnds[side][0][0], j + kEnds[side][0][1]);
        DiagramPoint out = node(i + kEnds[side][1][0], j + kEnds[side][1][1]);
        if (!inside(i + kEnds[side][0][0], j + kEnds[side][0][1])) std::swap(in, out);
        for (int k = 0; k < 34; ++k) {
            const DiagramPoint mid{0.5 * (in.z + out.z), 0.5 * (in.y + out.y)};
            (inside(mid) ? in : out) = mid;
        }
        return {0.5 * (in.z + out.z), 0.5 * (in.y + out.y)};
    }

    void cell(int i, int j) {
        const int index = inside(i, j) | inside(i + 1, j) << 1 | inside(i + 1, j + 1) << 2 |
                          inside(i, j + 1) << 3;
        if (index == 0 || index == 15) return;
        // Sides: 0 bottom, 1 right, 2 top, 3 left; a saddle is resolved by the centre.
        static constexpr int kSegments[16][4] = {
            {-1, -1, -1, -1}, {3, 0, -1, -1}, {0, 1, -1, -1}, {3, 1, -1, -1},
            {1, 2, -1, -1},   {3, 0, 1, 2},   {0, 2, -1, -1}, {3, 2, -1, -1},
            {2, 3, -1, -1},   {0, 2, -1, -1}, {0, 1, 2, 3},   {1, 2, -1, -1},
            {3, 1, -1, -1},   {0, 1, -1, -1}, {3, 0, -1, -1}, {-1, -1, -1, -1}};
        int sides[4] = {kSegments[index][0], kSegments[index][1], kSegments[index][2],
                        kSegments[index][3]};
        if (index == 5 || index == 10) {
            const DiagramPoint centre = node(i, j);
            if (inside({centre.z + 0.5 * m_step, centre.y + 0.5 * m_step})) {
                const int joined[2][4] = {{0, 1, 2, 3}, {3, 0, 1, 2}};  // 5, 10
                for (int k = 0; k < 4; ++k) sides[k] = joined[index == 10][k];
            }
        }
        for (int s = 0; s < 4 && sides[s] >= 0; s += 2) {
            const long a = vertex(i, j, sides[s]), b = vertex(i, j, sides[s + 1]);
            m_links[a].push_back(b);
            m_links[b].push_back(a);
        }
    }

    long vertex(int i, int j, int side) {
        const long id = edge_id(i, j, side);
        if (!m_points.count(id)) m_points.emplace(id, crossing(i, j, side));
        return id;
    }

    void chain(std::vector<SectionCurve>& out) {
        std::unordered_map<long, bool> used;
        // Open chains (cut by the grid's border, which the margin should prevent) first from
        // their ends, then the loops.
        for (int pass = 0; pass < 2; ++pass) {
            for (const auto& [start, links] : m_links) {
                if (used[start] || (pass == 0 && links.size() != 1)) continue;
                SectionCurve curve;
                long previous = -1, at = start;
                while (true) {
                    used[at] = true;
                    curve.points.push_back(m_points.at(at));
                    long next = -1;
                    for (long candidate : m_links.at(at)) {
                        if (candidate != previous && !used[candidate]) next = candidate;
                    }
                    if (next < 0) {
                        for (long candidate : m_links.at(at))
                            curve.closed |= candidate == start && curve.points.size() > 2;
                        break;
                    }
                    previous = at;
                    at = next;
                }
                if (curve.points.size() >= 2) out.push_back(std::move(curve));
            }
        }
    }

    const Shape& m_shape;
    const SectionPlane& m_plane;
    int m_n;
    double m_a0 = 0, m_b0 = 0, m_step = 1;
    std::vector<char> m_inside;
    std::unordered_map<long, DiagramPoint> m_points;
    std::unordered_map<long, std::vector<long>> m_links;
};

}  // namespace

std::vector<SectionCurve> section_outline(const Shape& shape, const SectionPlane& plane,
                                          const SectionOutlineOptions& options) {
    std::vector<SectionCurve> out;
    if (const std::optional<FlatPatch> flat = shape.flat_patch(); flat && flat->is_disc()) {
        section_cut_disc(*flat, plane, out);
    } else if (flat) {
        section_cut_polygon(flat->corners.data(), static_cast<int>(flat->corners.size()), plane,
                            out);
    } else if (const LensPrescription* lens = shape.lens_prescription();
               lens && section_holds_lens_axis(*lens, plane)) {
        // A lens cut through its axis: its faces' exact profile.
        constexpr int kSteps = 128;
        SectionCurve curve;
        curve.closed = true;
        for (const Vec3& p :
             shape.axial_outline(normalize(cross(plane.normal(), lens->axis)), kSteps)) {
            curve.points.push_back(plane.of(p));
        }
        out.push_back(std::move(curve));
    } else {
        // A mesh's triangles or a mirror's quads (48 rings by 96 sectors: a chord error under
        // 1e-3 of the radius for the curvatures mirrors have), else the solid's contour.
        bool faceted = false;
        shape.for_each_facet([&](const Vec3* corners, int count) {
            faceted = true;
            section_cut_polygon(corners, count, plane, out);
        });
        if (!faceted && shape.is_closed()) SolidContour(shape, plane, options.grid).run(out);
    }
    return out;
}

}  // namespace lenslab
