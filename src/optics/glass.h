#pragma once
// Refractive index as a function of wavelength, and the built-in glass catalogue.

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lenslab {

// Fraunhofer lines that define n_d and the Abbe number V_d = (n_d - 1) / (n_F - n_C)
// (ISO 7944: d = He 587.5618 nm, F = H 486.1327 nm, C = H 656.2725 nm).
inline constexpr double kLineD = 587.5618, kLineF = 486.1327, kLineC = 656.2725;

class IndexModel {
public:
    virtual ~IndexModel() = default;
    // Refractive index relative to standard air (20 degC, 1 atm) at a wavelength in air in
    // nm, as glass catalogues give it (air_index.h; a scene with "ambient": "vacuum" converts).
    virtual double n(double nm) const = 0;
    // False only for a constant index: then refraction does not split wavelengths.
    virtual bool dispersive() const { return true; }
    virtual std::string describe() const = 0;
    // Wavelengths (nm) over which the model's source vouches for it.
    double min_nm = 0, max_nm = 1e9;

    double n_d() const { return n(kLineD); }
    double abbe_number() const { return (n(kLineD) - 1.0) / (n(kLineF) - n(kLineC)); }
};

using IndexModelPtr = std::shared_ptr<const IndexModel>;

std::shared_ptr<IndexModel> constant_index(double n);
// n = A + B / l^2 + C / l^4, l in micrometres.
std::shared_ptr<IndexModel> cauchy_index(double a, double b_um2, double c_um4 = 0.0);
// n^2 = 1 + sum_i B_i l^2 / (l^2 - C_i), l in micrometres, C_i in um^2.
std::shared_ptr<IndexModel> sellmeier_index(std::vector<double> b, std::vector<double> c_um2);
// A two-term Cauchy through n_d with the Abbe number V_d: for glasses known only by their
// catalogue code (n_d, V_d).
std::shared_ptr<IndexModel> abbe_index(double n_d, double v_d);

struct Glass {
    std::string name;
    std::string description;
    std::string source;  // where the coefficients come from
    IndexModelPtr model;
    double datasheet_n_d;  // the source's published n_d and V_d, for checking (NaN if none)
    double datasheet_v_d;
    std::string maker =
        {};  // "SCHOTT", "OHARA", ... for a maker's catalogue glass; empty if built in
    // The extinction coefficient k against wavelength (um), where the catalogue gives it
    // (internal transmittance through d: exp(-4 pi k d / lambda)).
    std::vector<std::pair<double, double>> k_um = {};
};

// The built-in materials (optics/glass.cpp); the makers' catalogues are in glass_library.h.
const std::vector<Glass>& glass_catalogue();
// A glass by name, built-in first, then the makers' catalogues (see lookup_glass in
// glass_library.h for the rules); nullptr if unknown or ambiguous.
const Glass* find_glass(const std::string& name);

}  // namespace lenslab
