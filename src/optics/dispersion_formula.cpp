#include "optics/dispersion_formula.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lenslab {

namespace {

// Coefficient counts each formula accepts: the database writes only the terms it uses, so a
// formula of pairs takes C1 plus whole pairs, and the fixed-form ones take up to their length.
bool coefficient_count_fits(DispersionFormula f, size_t count, std::string& expected) {
    switch (f) {
        case DispersionFormula::Sellmeier:
        case DispersionFormula::Sellmeier2:
        case DispersionFormula::Polynomial:
        case DispersionFormula::Cauchy:
        case DispersionFormula::Gases:
            expected = "C1 and then pairs: an odd number, at least 3";
            return count >= 3 && count % 2 == 1;
        case DispersionFormula::RefractiveIndexInfo:
            expected = "1 to 17";
            return count >= 1 && count <= 17;
        case DispersionFormula::Herzberger:
            expected = "1 to 6";
            return count >= 1 && count <= 6;
        case DispersionFormula::Retro:
            expected = "1 to 4";
            return count >= 1 && count <= 4;
        case DispersionFormula::Exotic:
            expected = "1 to 6";
            return count >= 1 && count <= 6;
    }
    return false;
}

double coefficient_or_zero(const std::vector<double>& c, size_t one_based) {
    return one_based <= c.size() ? c[one_based - 1] : 0.0;
}

// n from n^2; a formula evaluated far outside its range can go negative, and no NaN may
// reach a ray, so it clamps at 0 (IndexModel users check the validity range first).
double root_of_square(double n2) { return std::sqrt(std::max(n2, 0.0)); }

class FormulaIndex final : public IndexModel {
public:
    FormulaIndex(DispersionFormula formula, std::vector<double> c)
        : m_formula(formula), m_c(std::move(c)) {}

    double n(double nm) const override {
        const double l = nm * 1e-3, l2 = l * l;
        const auto& c = m_c;
        auto C = [&](size_t i) { return coefficient_or_zero(c, i); };
        switch (m_formula) {
            case DispersionFormula::Sellmeier: {
                double s = 1.0 + C(1);
                for (size_t i = 1; i + 1 < c.size(); i += 2)
                    s += c[i] * l2 / (l2 - c[i + 1] * c[i + 1]);
                return root_of_square(s);
            }
            case DispersionFormula::Sellmeier2: {
                double s = 1.0 + C(1);
                for (size_t i = 1; i + 1 < c.size(); i += 2) s += c[i] * l2 / (l2 - c[i + 1]);
                return root_of_square(s);
            }
            case DispersionFormula::Polynomial: {
                double s = C(1);
                for (size_t i = 1; i + 1 < c.size(); i += 2) s += c[i] * std::pow(l, c[i + 1]);
                return root_of_square(s);
            }
            case DispersionFormula::RefractiveIndexInfo: {
                double s = C(1);
                for (size_t i : {2u, 6u}) {
                    if (C(i) != 0.0)
                        s += C(i) * std::pow(l, C(i + 1)) / (l2 - std::pow(C(i + 2), C(i + 3)));
                }
                for (size_t i = 10; i <= 16; i += 2) {
                    if (C(i) != 0.0) s += C(i) * std::pow(l, C(i + 1));
                }
                return root_of_square(s);
            }
            case DispersionFormula::Cauchy: {
                double s = C(1);
                for (size_t i = 1; i + 1 < c.size(); i += 2) s += c[i] * std::pow(l, c[i + 1]);
                return s;
            }
            case DispersionFormula::Gases: {
                double s = 1.0 + C(1);
                for (size_t i = 1; i + 1 < c.size(); i += 2) s += c[i] / (c[i + 1] - 1.0 / l2);
                return s;
            }
            case DispersionFormula::Herzberger: {
                const double big_l = 1.0 / (l2 - 0.028);
                return C(1) + C(2) * big_l + C(3) * big_l * big_l + C(4) * l2 + C(5) * l2 * l2 +
                       C(6) * l2 * l2 * l2;
            }
            case DispersionFormula::Retro: {
                // Lorentz-Lorenz: r = (n^2 - 1) / (n^2 + 2), so n^2 = (1 + 2r) / (1 - r).
                const double r = C(1) + C(2) * l2 / (l2 - C(3)) + C(4) * l2;
                return root_of_square((1.0 + 2.0 * r) / (1.0 - r));
            }
            case DispersionFormula::Exotic: {
                const double d = l - C(5);
                return root_of_square(C(1) + C(2) / (l2 - C(3)) + C(4) * d / (d * d + C(6)));
            }
        }
        return 0.0;
    }

    std::string describe() const override {
        std::ostringstream s;
        s << formula_name(static_cast<int>(m_formula)) << " (refractiveindex.info formula "
          << static_cast<int>(m_formula) << ", " << m_c.size() << " coefficients)";
        return s.str();
    }

private:
    DispersionFormula m_formula;
    std::vector<double> m_c;
};

class TabulatedIndex final : public IndexModel {
public:
    explicit TabulatedIndex(std::vector<std::pair<double, double>> um_n)
        : m_points(std::move(um_n)) {}

    double n(double nm) const override {
        const double l = nm * 1e-3;
        if (l <= m_points.front().first) return m_points.front().second;
        if (l >= m_points.back().first) return m_points.back().second;
        const auto hi = std::upper_bound(m_points.begin(), m_points.end(), l,
                                         [](double x, const auto& p) { return x < p.first; });
        const auto lo = hi - 1;
        const double t = (l - lo->first) / (hi->first - lo->first);
        return lo->second + t * (hi->second - lo->second);
    }

    std::string describe() const override {
        return "tabulated n at " + std::to_string(m_points.size()) + " wavelengths (linear)";
    }

private:
    std::vector<std::pair<double, double>> m_points;
};

}  // namespace

std::string formula_name(int formula) {
    static const char* const names[] = {
        "Sellmeier",  "Sellmeier-2", "polynomial", "RefractiveIndex.INFO", "Cauchy", "gases",
        "Herzberger", "Retro",       "Exotic"};
    return formula >= 1 && formula <= 9 ? names[formula - 1] : "unknown";
}

std::shared_ptr<IndexModel> formula_index(int formula, std::vector<double> coefficients,
                                          double min_um, double max_um) {
    if (formula < 1 || formula > 9) {
        throw DispersionDataError("formula " + std::to_string(formula) +
                                  " is not one of the database's formulas 1-9");
    }
    const auto f = static_cast<DispersionFormula>(formula);
    std::string expected;
    if (!coefficient_count_fits(f, coefficients.size(), expected)) {
        throw DispersionDataError(formula_name(formula) + " (formula " + std::to_string(formula) +
                                  ") takes " + expected + " coefficients, got " +
                                  std::to_string(coefficients.size()));
    }
    for (double c : coefficients) {
        if (!std::isfinite(c)) throw DispersionDataError("a coefficient is not a finite number");
    }
    if (!(min_um > 0.0) || !(max_um > min_um) || !std::isfinite(max_um)) {
        std::ostringstream s;
        s << "the wavelength range " << min_um << " - " << max_um
          << " um is not a positive, increasing pair";
        throw DispersionDataError(s.str());
    }
    auto model = std::make_shared<FormulaIndex>(f, std::move(coefficients));
    model->min_nm = min_um * 1e3;
    model->max_nm = max_um * 1e3;
    return model;
}

std::shared_ptr<IndexModel> tabulated_index(std::vector<std::pair<double, double>> um_n) {
    if (um_n.size() < 2) {
        throw DispersionDataError("an index table needs at least two wavelengths, got " +
                                  std::to_string(um_n.size()));
    }
    for (size_t i = 0; i < um_n.size(); ++i) {
        const auto [l, n] = um_n[i];
        if (!(l > 0.0) || !std::isfinite(l) || !(n > 0.0) || !std::isfinite(n)) {
            throw DispersionDataError("table row " + std::to_string(i + 1) +
                                      ": wavelength and n must be positive numbers");
        }
        if (i > 0 && !(l > um_n[i - 1].first)) {
            throw DispersionDataError("table row " + std::to_string(i + 1) +
                                      ": wavelengths must increase");
        }
    }
    const double min_nm = um_n.front().first * 1e3, max_nm = um_n.back().first * 1e3;
    auto model = std::make_shared<TabulatedIndex>(std::move(um_n));
    model->min_nm = min_nm;
    model->max_nm = max_nm;
    return model;
}

}  // namespace lenslab
