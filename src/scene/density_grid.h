#pragma once
// A density given as samples on a regular grid (a smoke simulation's output, a scanned
// plume): nx x ny x nz values at the points of a lattice spanning a box, corner to corner,
// interpolated trilinearly between them and 0 outside the box. Trilinear interpolation
// never exceeds the largest sample, so that is an exact majorant.

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "math/aabb.h"

namespace lenslab {

class DensityGrid {
public:
    // `values` x fastest, then y, then z: value (i, j, k) at [(k ny + j) nx + i]. Each count
    // >= 1 (an axis of 1 is constant along it), values finite and >= 0 (the reader checks).
    DensityGrid(int nx, int ny, int nz, const Aabb& box, std::vector<double> values);

    double at(const Vec3& p) const;
    double max() const { return m_max; }
    const Aabb& box() const { return m_box; }

private:
    int m_n[3];
    Aabb m_box;
    std::vector<double> m_values;
    double m_max = 0;
};

// Reads `{"grid": [nx, ny, nz], "box": [[x0, y0, z0], [x1, y1, z1]], "values": [...]}` at
// JSON path `path`. Throws SceneError naming the key (or the value) at fault.
DensityGrid read_density_grid(const nlohmann::json& j, const std::string& path);

}  // namespace lenslab
