#include "optics/absorption.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lenslab {

double beer_lambert(double alpha, double distance) { return std::exp(-alpha * distance); }

double absorption_per_mm(const std::vector<std::pair<double, double>>& k_um, double nm) {
    if (k_um.empty()) return 0.0;
    const double um = nm * 1e-3;
    double k;
    if (um <= k_um.front().first) {
        k = k_um.front().second;
    } else if (um >= k_um.back().first) {
        k = k_um.back().second;
    } else {
        const auto hi = std::upper_bound(k_um.begin(), k_um.end(), um,
                                         [](double x, const auto& p) { return x < p.first; });
        const auto lo = hi - 1;
        const double t = (um - lo->first) / (hi->first - lo->first);
        k = lo->second + t * (hi->second - lo->second);
    }
    return 4.0 * std::numbers::pi * k / (nm * 1e-6);  // lambda in mm
}

double internal_transmittance(const std::vector<std::pair<double, double>>& k_um, double nm,
                              double thickness_mm) {
    return beer_lambert(absorption_per_mm(k_um, nm), thickness_mm);
}

Absorption::Absorption(std::vector<std::pair<double, double>> k_um, double unit_mm)
    : m_k_um(std::move(k_um)), m_unit_mm(unit_mm) {}

}  // namespace lenslab
