#include "scene/surface_shapes.h"

namespace lenslab {

// Each shape's file defines its entry: conic_surface_shapes.cpp the four surfaces of
// revolution in closed form, polynomial_surface_shapes.cpp the two polynomial freeforms.
SurfaceShapeEntry flat_surface_shape();
SurfaceShapeEntry sphere_surface_shape();
SurfaceShapeEntry conic_surface_shape();
SurfaceShapeEntry asphere_surface_shape();
SurfaceShapeEntry biconic_surface_shape();
SurfaceShapeEntry toroidal_surface_shape();
SurfaceShapeEntry xy_polynomial_surface_shape();
SurfaceShapeEntry zernike_surface_shape();
SurfaceShapeEntry sag_surface_shape();

const std::vector<SurfaceShapeEntry>& surface_shapes() {
    static const std::vector<SurfaceShapeEntry> shapes{
        flat_surface_shape(),          sphere_surface_shape(),  conic_surface_shape(),
        asphere_surface_shape(),       biconic_surface_shape(), toroidal_surface_shape(),
        xy_polynomial_surface_shape(), zernike_surface_shape(), sag_surface_shape(),
    };
    return shapes;
}

const SurfaceShapeEntry* find_surface_shape(const std::string& name) {
    for (const SurfaceShapeEntry& e : surface_shapes()) {
        if (e.name == name) return &e;
    }
    return nullptr;
}

}  // namespace lenslab
