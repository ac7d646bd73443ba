#pragma once
// The cells a detector bins light into: a regular grid over the bounding rectangle of a
// flat surface in its own (u, v) coordinates, each cell knowing the area of its overlap
// with the surface (a disc's rim cells are partly outside it), so power / area is the
// irradiance even at the edge.

#include <vector>

#include "geometry/plane_frame.h"
#include "scene/scene.h"

namespace lenslab {

class DetectorGrid {
public:
    // The grid of a triangle, disc or rectangle object with detector settings; throws
    // std::invalid_argument for any other object.
    static DetectorGrid for_object(const SceneObject& object);

    // (u, v) origin and axes: a disc's or rectangle's centre, a triangle's first vertex
    // (u along its first edge).
    const PlaneFrame& frame() const { return m_frame; }
    int cells_u() const { return m_nu; }
    int cells_v() const { return m_nv; }
    int cell_count() const { return m_nu * m_nv; }
    double u_min() const { return m_u0; }
    double u_max() const { return m_u1; }
    double v_min() const { return m_v0; }
    double v_max() const { return m_v1; }
    double cell_width() const { return (m_u1 - m_u0) / m_nu; }
    double cell_height() const { return (m_v1 - m_v0) / m_nv; }

    // Cells are numbered row by row from the lowest v: index = iv * cells_u + iu.
    int cell_at(double u, double v) const;
    double cell_u(int cell) const { return m_u0 + (cell % m_nu + 0.5) * cell_width(); }  // centre
    double cell_v(int cell) const { return m_v0 + (cell / m_nu + 0.5) * cell_height(); }
    // Area of the cell's overlap with the surface (0 for a cell wholly outside it).
    double cell_area(int cell) const { return m_area[static_cast<size_t>(cell)]; }
    double surface_area() const;

private:
    PlaneFrame m_frame;
    int m_nu = 1, m_nv = 1;
    double m_u0 = 0, m_u1 = 1, m_v0 = 0, m_v1 = 1;
    std::vector<double> m_area;
};

// Area of the overlap of the rectangle [u0, u1] x [v0, v1] with the disc of radius r
// about the origin, and with a triangle given by its (u, v) corners.
double rectangle_disc_overlap(double u0, double u1, double v0, double v1, double r);
double rectangle_triangle_overlap(double u0, double u1, double v0, double v1,
                                  const double (&tri)[3][2]);

}  // namespace lenslab
