#include "optics/air_index.h"

namespace lenslab {

namespace {

// Birch & Downs (1993, 1994): (n - 1) of standard air (15 degC, 101 325 Pa, dry, 400 ppm CO2)
// from the vacuum wavenumber sigma in 1/um, then scaled to temperature t (degC) and pressure p.
double air_refractivity_at_vacuum_nm(double vacuum_nm) {
    const double s2 = (1e3 / vacuum_nm) * (1e3 / vacuum_nm);
    const double standard = (8342.54 + 2406147.0 / (130.0 - s2) + 15998.0 / (38.9 - s2)) * 1e-8;
    const double t = 20.0, p = 101325.0;
    return p * standard / 96095.43 * (1.0 + 1e-8 * (0.601 - 0.00972 * t) * p) /
           (1.0 + 0.0036610 * t);
}

// Catalogue (air) wavelengths in, vacuum-referred model evaluated at the vacuum wavelength.
class AirRelativeIndex final : public IndexModel {
public:
    explicit AirRelativeIndex(IndexModelPtr absolute) : m_absolute(std::move(absolute)) {
        // The range stays the source's (a 0.03% shift in wavelength is below its precision).
        min_nm = m_absolute->min_nm;
        max_nm = m_absolute->max_nm;
    }
    double n(double air_nm) const override {
        const double n_air = standard_air_index(air_nm);
        return m_absolute->n(air_nm * n_air) / n_air;
    }
    std::string describe() const override {
        return m_absolute->describe() + ", converted from vacuum to standard air";
    }

private:
    IndexModelPtr m_absolute;
};

class VacuumRelativeIndex final : public IndexModel {
public:
    explicit VacuumRelativeIndex(IndexModelPtr relative) : m_relative(std::move(relative)) {
        min_nm = m_relative->min_nm;
        max_nm = m_relative->max_nm;
    }
    double n(double vacuum_nm) const override {
        const double n_air = 1.0 + air_refractivity_at_vacuum_nm(vacuum_nm);
        return m_relative->n(vacuum_nm / n_air) * n_air;
    }
    bool dispersive() const override { return true; }
    std::string describe() const override {
        return m_relative->describe() + ", as an absolute index (ambient vacuum)";
    }

private:
    IndexModelPtr m_relative;
};

}  // namespace

double standard_air_index(double air_nm) {
    // The formula takes the vacuum wavelength; one fixed-point step from the air wavelength
    // is exact to 1e-11 (n - 1 changes by 1e-7 across the shift).
    const double first = 1.0 + air_refractivity_at_vacuum_nm(air_nm);
    return 1.0 + air_refractivity_at_vacuum_nm(air_nm * first);
}

double vacuum_wavelength(double air_nm) { return air_nm * standard_air_index(air_nm); }

std::shared_ptr<IndexModel> relative_to_air(IndexModelPtr absolute) {
    return std::make_shared<AirRelativeIndex>(std::move(absolute));
}

std::shared_ptr<IndexModel> relative_to_vacuum(IndexModelPtr relative_to_air) {
    return std::make_shared<VacuumRelativeIndex>(std::move(relative_to_air));
}

}  // namespace lenslab
