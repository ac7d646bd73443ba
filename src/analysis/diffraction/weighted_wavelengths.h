#pragma once
// The wavelengths of a polychromatic figure (field_mtf.h, field_psf.h) with their weights,
// checked once: none given means the first-order data's wavelength alone, no weights mean
// equal ones.

#include <stdexcept>
#include <vector>

#include "analysis/system/first_order.h"

namespace lenslab {

struct WeightedWavelengths {
    std::vector<double> nm, weights;
    double total = 0;  // Σ weights
};

// Throws std::invalid_argument when the weights do not match the wavelengths one for one or
// add up to zero.
inline WeightedWavelengths weighted_wavelengths(const FirstOrder& first_order,
                                                const std::vector<double>& wavelengths,
                                                const std::vector<double>& weights) {
    WeightedWavelengths w;
    w.nm = wavelengths.empty() ? std::vector<double>{first_order.wavelength_nm} : wavelengths;
    w.weights = weights.empty() ? std::vector<double>(w.nm.size(), 1.0) : weights;
    if (w.weights.size() != w.nm.size()) throw std::invalid_argument("one weight per wavelength");
    for (double v : w.weights) w.total += v;
    if (!(w.total > 0)) throw std::invalid_argument("the wavelengths' weights add up to zero");
    return w;
}

}  // namespace lenslab
