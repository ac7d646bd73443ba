#pragma once
// Absorption inside a medium: the Beer-Lambert law, one helper for every absorbing thing (a
// glass's extinction coefficient k today, a participating medium's coefficient later).

#include <memory>
#include <utility>
#include <vector>

namespace lenslab {

// Beer-Lambert: the fraction of light left after `distance` through a medium of absorption
// coefficient `alpha` (per the same length unit).
double beer_lambert(double alpha, double distance);

// The absorption coefficient alpha = 4 pi k / lambda, per millimetre, of a medium whose
// extinction coefficient k is tabulated against wavelength in um (strictly increasing). k is
// interpolated linearly; outside the table it holds the nearest end's value (catalogues stop
// at their measured range, and the glass does not become clear past it).
double absorption_per_mm(const std::vector<std::pair<double, double>>& k_um, double nm);

// The internal transmittance of `thickness_mm` of such a medium (no surface reflections), the
// figure glass catalogues print for 10 mm and 25 mm.
double internal_transmittance(const std::vector<std::pair<double, double>>& k_um, double nm,
                              double thickness_mm);

// What the renderer needs of an absorbing medium: alpha per scene length unit at a wavelength.
class Absorption {
public:
    // A glass's k table, with the length of one scene unit in millimetres.
    Absorption(std::vector<std::pair<double, double>> k_um, double unit_mm);
    double per_unit(double nm) const { return absorption_per_mm(m_k_um, nm) * m_unit_mm; }
    // The fraction left after `distance` scene units at wavelength nm.
    double transmittance(double nm, double distance) const {
        return beer_lambert(per_unit(nm), distance);
    }

private:
    std::vector<std::pair<double, double>> m_k_um;
    double m_unit_mm;
};

using AbsorptionPtr = std::shared_ptr<const Absorption>;

}  // namespace lenslab
