#include "optics/fresnel.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

FresnelTerms fresnel_dielectric(double cos_i, double eta_i, double eta_t) {
    cos_i = std::clamp(cos_i, 0.0, 1.0);
    const double sin_i2 = 1.0 - cos_i * cos_i;
    const double sin_t2 = (eta_i / eta_t) * (eta_i / eta_t) * sin_i2;
    if (sin_t2 >= 1.0) return {1.0, 1.0, true};
    const double cos_t = std::sqrt(1.0 - sin_t2);
    const double rs = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    const double rp = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
    return {rs * rs, rp * rp, false};
}

}  // namespace lenslab
