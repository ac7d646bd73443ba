#include "scene/density_grid.h"

#include <algorithm>
#include <cmath>

#include "scene/box_corners_json.h"
#include "scene/json_reader.h"

namespace lenslab {

namespace {

// Samples per axis at most, and in all: a 512^3 grid is 1 GiB of doubles already.
constexpr int64_t kMaxGridSide = 1024;
constexpr int64_t kMaxGridValues = int64_t{1} << 26;

}  // namespace

DensityGrid::DensityGrid(int nx, int ny, int nz, const Aabb& box, std::vector<double> values)
    : m_n{nx, ny, nz}, m_box(box), m_values(std::move(values)) {
    for (const double v : m_values) m_max = std::max(m_max, v);
}

double DensityGrid::at(const Vec3& p) const {
    if (!m_box.contains(p)) return 0.0;
    // Per axis: the lattice cell holding p and p's fraction across it.
    int i0[3];
    double u[3];
    for (int a = 0; a < 3; ++a) {
        const double cells = m_n[a] - 1;
        const double x = cells * (p[a] - m_box.lo[a]) / (m_box.hi[a] - m_box.lo[a]);
        i0[a] = std::clamp(static_cast<int>(x), 0, std::max(0, m_n[a] - 2));
        u[a] = m_n[a] > 1 ? std::clamp(x - i0[a], 0.0, 1.0) : 0.0;
    }
    const auto value = [&](int di, int dj, int dk) {
        const int i = std::min(i0[0] + di, m_n[0] - 1), j = std::min(i0[1] + dj, m_n[1] - 1),
                  k = std::min(i0[2] + dk, m_n[2] - 1);
        return m_values[(size_t(k) * size_t(m_n[1]) + size_t(j)) * size_t(m_n[0]) + size_t(i)];
    };
    double sum = 0;
    for (int c = 0; c < 8; ++c) {
        const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
        const double w = (di ? u[0] : 1 - u[0]) * (dj ? u[1] : 1 - u[1]) * (dk ? u[2] : 1 - u[2]);
        if (w > 0) sum += w * value(di, dj, dk);
    }
    return sum;
}

DensityGrid read_density_grid(const nlohmann::json& j, const std::string& path) {
    JsonObjectReader r(j, path, {"grid", "box", "values"}, "a density grid");
    const nlohmann::json& counts = r.require("grid");
    const std::string counts_path = r.child_path("grid");
    if (!counts.is_array() || counts.size() != 3) {
        throw SceneError(counts_path, "must be three whole numbers [nx, ny, nz]");
    }
    int n[3];
    int64_t total = 1;
    for (int a = 0; a < 3; ++a) {
        const std::string where = counts_path + "[" + std::to_string(a) + "]";
        const double c = JsonObjectReader::as_number(counts[size_t(a)], where);
        if (c != std::floor(c) || c < 1 || c > kMaxGridSide) {
            throw SceneError(where, "must be a whole number from 1 to " +
                                        std::to_string(kMaxGridSide) + ", got " + format_number(c));
        }
        n[a] = static_cast<int>(c);
        total *= n[a];
    }
    if (total > kMaxGridValues) {
        throw SceneError(counts_path, "holds " + std::to_string(total) + " values, more than the " +
                                          std::to_string(kMaxGridValues) + " allowed");
    }
    const Aabb box = read_box_corners(r.require("box"), r.child_path("box"));
    const nlohmann::json& v = r.require("values");
    const std::string values_path = r.child_path("values");
    if (!v.is_array() || int64_t(v.size()) != total) {
        throw SceneError(values_path, "must be an array of nx ny nz = " + std::to_string(total) +
                                          " numbers (x fastest, then y, then z), got " +
                                          (v.is_array() ? std::to_string(v.size()) : "no array"));
    }
    std::vector<double> values(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
        const std::string where = values_path + "[" + std::to_string(i) + "]";
        values[i] = JsonObjectReader::as_number(v[i], where);
        if (values[i] < 0) {
            throw SceneError(where, "is " + format_number(values[i]) + ": a density must be >= 0");
        }
    }
    return DensityGrid(n[0], n[1], n[2], box, std::move(values));
}

}  // namespace lenslab
