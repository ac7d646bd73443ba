#include "optics/agf_catalogue.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "optics/dispersion_formula.h"
#include "optics/glass_catalogue_file.h"

namespace lenslab {

namespace {

// A UTF-16 file (Zemax writes them so) as ASCII: characters beyond ASCII become '?', which
// only comment lines hold.
std::string agf_text(const std::string& bytes) {
    const bool le = bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0xFF &&
                    static_cast<unsigned char>(bytes[1]) == 0xFE;
    const bool be = bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0xFE &&
                    static_cast<unsigned char>(bytes[1]) == 0xFF;
    if (!le && !be) {
        // A UTF-8 byte order mark is skipped; the rest is read byte by byte.
        if (bytes.rfind("\xEF\xBB\xBF", 0) == 0) return bytes.substr(3);
        return bytes;
    }
    std::string out;
    out.reserve(bytes.size() / 2);
    for (size_t i = 2; i + 1 < bytes.size(); i += 2) {
        const unsigned lo = static_cast<unsigned char>(bytes[le ? i : i + 1]);
        const unsigned hi = static_cast<unsigned char>(bytes[le ? i + 1 : i]);
        const unsigned c = lo | (hi << 8);
        out.push_back(c < 0x80 ? static_cast<char>(c) : '?');
    }
    return out;
}

struct AgfLine {
    const std::string& source;
    int number;

    [[noreturn]] void fail(const std::string& why) const {
        throw GlassDataError(source + ":" + std::to_string(number) + ": " + why);
    }

    double number_at(const std::vector<std::string>& words, size_t i, const char* what) const {
        if (i >= words.size()) fail(std::string("missing ") + what);
        const std::string& w = words[i];
        char* end = nullptr;
        const double v = std::strtod(w.c_str(), &end);
        if (end == w.c_str() || *end != '\0' || !std::isfinite(v)) {
            std::string why = what;
            why.append(" must be a number, got '").append(w).append("'");
            fail(why);
        }
        return v;
    }
};

// One glass as the lines after its NM line build it.
struct AgfGlass {
    Glass glass;
    int formula = 0;
    int line = 0;  // of its NM line
    std::vector<double> cd;
    double min_um = 0, max_um = 0;
    std::vector<std::pair<double, double>> k_um;
};

// Internal transmittance tau through d mm at lambda um as an extinction coefficient:
// tau = exp(-4 pi k d / lambda). tau 0 (opaque) is taken as 1e-9, tau above 1 (rounding) as 1.
double agf_k_from_transmittance(double um, double tau, double mm) {
    const double t = std::clamp(tau, 1e-9, 1.0);
    return -std::log(t) * (um * 1e-3) / (4.0 * std::numbers::pi * mm);
}

Glass finish_agf_glass(AgfGlass& g, const std::string& source) {
    const AgfLine at{source, g.line};
    if (g.cd.empty()) at.fail("glass " + g.glass.name + " has no CD line (its coefficients)");
    if (!(g.max_um > g.min_um)) {
        // No LD line: Zemax's own default range for visible glass data.
        g.min_um = 0.35;
        g.max_um = 2.5;
    }
    try {
        g.glass.model = agf_formula_index(g.formula, g.cd, g.min_um, g.max_um);
    } catch (const DispersionDataError& e) {
        at.fail("glass " + g.glass.name + ": " + e.what());
    } catch (const GlassDataError& e) {
        at.fail("glass " + g.glass.name + ": " + e.what());
    }
    // Sorted by wavelength, one value per wavelength (the first, usually 10 mm).
    std::stable_sort(g.k_um.begin(), g.k_um.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    g.k_um.erase(std::unique(g.k_um.begin(), g.k_um.end(),
                             [](const auto& a, const auto& b) { return a.first == b.first; }),
                 g.k_um.end());
    g.glass.k_um = std::move(g.k_um);
    return std::move(g.glass);
}

std::vector<std::string> agf_words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

}  // namespace

IndexModelPtr agf_formula_index(int formula, const std::vector<double>& cd, double min_um,
                                double max_um) {
    auto c = [&](size_t i) { return i < cd.size() ? cd[i] : 0.0; };
    // Each AGF formula written as one of the refractiveindex.info forms (dispersion_formula.h).
    std::vector<double> rii;
    int rii_formula = 0;
    auto power_series = [&](std::initializer_list<double> powers) {
        rii_formula = 3;  // n^2 = C1 + sum C_i l^C_{i+1}
        rii = {c(0)};
        size_t i = 1;
        for (double p : powers) rii.insert(rii.end(), {c(i++), p});
    };
    auto sellmeier = [&](size_t terms, double constant) {
        rii_formula = 2;  // n^2 - 1 = C1 + sum C_i l^2 / (l^2 - C_{i+1})
        rii = {constant};
        const size_t first = formula == 9 ? 1 : 0;  // Sellmeier 4's A comes first
        for (size_t t = 0; t < terms; ++t)
            rii.insert(rii.end(), {c(first + 2 * t), c(first + 2 * t + 1)});
    };
    switch (formula) {
        case 1:  // Schott: n^2 = a0 + a1 l^2 + a2 l^-2 + a3 l^-4 + a4 l^-6 + a5 l^-8
            power_series({2, -2, -4, -6, -8});
            break;
        case 2:  // Sellmeier 1: n^2 - 1 = sum_{3} K_i l^2 / (l^2 - L_i)
            sellmeier(3, 0.0);
            break;
        case 3:  // Herzberger: n = A + B L + C L^2 + D l^2 + E l^4 + F l^6, L = 1/(l^2 - 0.028)
            rii_formula = 7;
            rii = {c(0), c(1), c(2), c(3), c(4), c(5)};
            break;
        case 4:  // Sellmeier 2: n^2 - 1 = A + B1 l^2 / (l^2 - l1^2) + B2 / (l^2 - l2^2)
            rii_formula = 4;
            rii = {1.0 + c(0), c(1), 2, c(2), 2, c(3), 0, c(4), 2};
            break;
        case 5:  // Conrady: n = n0 + A / l + B / l^3.5
            rii_formula = 5;
            rii = {c(0), c(1), -1, c(2), -3.5};
            break;
        case 6:  // Sellmeier 3: four terms
            sellmeier(4, 0.0);
            break;
        case 7:  // Handbook of Optics 1: n^2 = A + B / (l^2 - C) - D l^2
            rii_formula = 4;
            rii = {c(0), c(1), 0, c(2), 1, 0, 0, 0, 1, -c(3), 2};
            break;
        case 8:  // Handbook of Optics 2: n^2 = A + B l^2 / (l^2 - C) - D l^2
            rii_formula = 4;
            rii = {c(0), c(1), 2, c(2), 1, 0, 0, 0, 1, -c(3), 2};
            break;
        case 9:  // Sellmeier 4: n^2 = A + B l^2 / (l^2 - C) + D l^2 / (l^2 - E)
            sellmeier(2, c(0) - 1.0);
            break;
        case 10:  // Extended: Schott plus a6 l^-10 + a7 l^-12
            power_series({2, -2, -4, -6, -8, -10, -12});
            break;
        case 11:  // Sellmeier 5: five terms
            sellmeier(5, 0.0);
            break;
        case 12:  // Extended 2: Schott plus a6 l^4 + a7 l^6
            power_series({2, -2, -4, -6, -8, 4, 6});
            break;
        case 13:  // Extended 3: a0 + a1 l^2 + a2 l^4 + a3 l^-2 + ... + a8 l^-12
            power_series({2, 4, -2, -4, -6, -8, -10, -12});
            break;
        default:
            throw GlassDataError("dispersion formula " + std::to_string(formula) +
                                 " is not one of Zemax's formulas 1-13");
    }
    return formula_index(rii_formula, std::move(rii), min_um, max_um);
}

std::vector<Glass> parse_agf_catalogue(const std::string& bytes, const std::string& source,
                                       const std::string& maker) {
    const std::string text = agf_text(bytes);
    std::vector<Glass> out;
    std::optional<AgfGlass> current;
    std::istringstream in(text);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        const AgfLine at{source, number};
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find('\0') != std::string::npos) {
            at.fail("holds NUL characters: UTF-16 without a byte order mark is not read");
        }
        const std::vector<std::string> words = agf_words(line);
        if (words.empty()) continue;
        const std::string& code = words[0];
        if (code == "CC" || code == "GC" || code == "ED" || code == "TD" || code == "OD" ||
            code == "BD") {
            continue;  // comments, thermal, chemical and other data
        }
        if (code == "NM") {
            if (current) out.push_back(finish_agf_glass(*current, source));
            current.emplace();
            if (words.size() < 2) at.fail("NM line without a glass name");
            current->line = number;
            current->glass.name = words[1];
            const double f = at.number_at(words, 2, "the dispersion formula number");
            if (f != std::floor(f) || f < 1 || f > 13) {
                at.fail("dispersion formula " + words[2] + " is not one of Zemax's formulas 1-13");
            }
            current->formula = static_cast<int>(f);
            // MIL code at 3; n_d and V_d (for checking) at 4 and 5, when present.
            const double nan = std::numeric_limits<double>::quiet_NaN();
            current->glass.datasheet_n_d = words.size() > 4 ? at.number_at(words, 4, "n_d") : nan;
            current->glass.datasheet_v_d = words.size() > 5 ? at.number_at(words, 5, "V_d") : nan;
            current->glass.maker = maker;
            current->glass.description = maker + " glass (user catalogue)";
            current->glass.source = source;
            continue;
        }
        if (!current) at.fail("'" + code + "' line before the first NM (glass) line");
        if (code == "CD") {
            for (size_t i = 1; i < words.size(); ++i)
                current->cd.push_back(at.number_at(words, i, "a CD coefficient"));
            if (current->cd.empty()) at.fail("CD line without coefficients");
        } else if (code == "LD") {
            current->min_um = at.number_at(words, 1, "the shortest wavelength (um)");
            current->max_um = at.number_at(words, 2, "the longest wavelength (um)");
            if (!(current->min_um > 0) || !(current->max_um > current->min_um))
                at.fail("LD range must be 0 < min < max (um)");
        } else if (code == "IT") {
            const double um = at.number_at(words, 1, "the IT wavelength (um)");
            const double tau = at.number_at(words, 2, "the internal transmittance");
            const double mm = at.number_at(words, 3, "the IT thickness (mm)");
            if (!(um > 0) || !(mm > 0) || tau < 0)
                at.fail("IT needs a wavelength > 0, a transmittance >= 0 and a thickness > 0");
            current->k_um.emplace_back(um, agf_k_from_transmittance(um, tau, mm));
        } else {
            at.fail("unknown line '" + code +
                    "' (an AGF file has NM, CD, LD, IT, CC, GC, ED, TD, OD, BD lines)");
        }
    }
    if (current) out.push_back(finish_agf_glass(*current, source));
    if (out.empty()) throw GlassDataError(source + ": no glass (NM line) in the file");
    return out;
}

std::vector<Glass> read_agf_catalogue(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw GlassDataError(path + ": not a glass catalogue file (missing or not a file)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw GlassDataError(path + ": cannot open the glass catalogue");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    std::string maker = std::filesystem::path(path).stem().string();
    std::transform(maker.begin(), maker.end(), maker.begin(),
                   [](unsigned char ch) { return std::toupper(ch); });
    return parse_agf_catalogue(bytes.str(), path, maker);
}

}  // namespace lenslab
