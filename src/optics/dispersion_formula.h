#pragma once
// The dispersion formulas of the refractiveindex.info database (its "formula 1" to "formula 9")
// and tabulated indices, as IndexModels. Glass catalogues give them with wavelengths in
// micrometres; IndexModel::n takes nanometres and converts.

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "optics/glass.h"

namespace lenslab {

// The database's numbering, kept so data files and its format description read alike.
enum class DispersionFormula {
    Sellmeier = 1,            // n^2 - 1 = C1 + sum C_i l^2 / (l^2 - C_{i+1}^2)
    Sellmeier2 = 2,           // n^2 - 1 = C1 + sum C_i l^2 / (l^2 - C_{i+1})
    Polynomial = 3,           // n^2 = C1 + sum C_i l^C_{i+1}
    RefractiveIndexInfo = 4,  // n^2 = C1 + two Sellmeier-like poles + four power terms
    Cauchy = 5,               // n = C1 + sum C_i l^C_{i+1}
    Gases = 6,                // n - 1 = C1 + sum C_i / (C_{i+1} - l^-2)
    Herzberger = 7,  // n = C1 + C2 L + C3 L^2 + C4 l^2 + C5 l^4 + C6 l^6, L = 1/(l^2 - 0.028)
    Retro = 8,       // (n^2 - 1) / (n^2 + 2) = C1 + C2 l^2 / (l^2 - C3) + C4 l^2
    Exotic = 9,      // n^2 = C1 + C2 / (l^2 - C3) + C4 (l - C5) / ((l - C5)^2 + C6)
};

// Thrown for coefficients a formula cannot take; the message says why.
class DispersionDataError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A formula with its coefficients, valid from min_um to max_um. Throws DispersionDataError for
// a formula number outside 1-9 or a coefficient count the formula does not accept.
std::shared_ptr<IndexModel> formula_index(int formula, std::vector<double> coefficients,
                                          double min_um, double max_um);

// Linear interpolation in (wavelength um, n) points, strictly increasing in wavelength; valid
// over the table. Throws DispersionDataError for fewer than two points or unsorted ones.
std::shared_ptr<IndexModel> tabulated_index(std::vector<std::pair<double, double>> um_n);

// "Sellmeier-2", "Herzberger", ...: the formula's name in the database's description.
std::string formula_name(int formula);

}  // namespace lenslab
