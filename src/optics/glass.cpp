#include "optics/glass.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "optics/air_index.h"

namespace lenslab {

namespace {

class ConstantIndex final : public IndexModel {
public:
    explicit ConstantIndex(double n) : m_n(n) {}
    double n(double) const override { return m_n; }
    bool dispersive() const override { return false; }
    std::string describe() const override {
        std::ostringstream s;
        s << "constant n = " << m_n;
        return s.str();
    }

private:
    double m_n;
};

class CauchyIndex final : public IndexModel {
public:
    CauchyIndex(double a, double b, double c) : m_a(a), m_b(b), m_c(c) {}
    double n(double nm) const override {
        const double l2 = (nm * 1e-3) * (nm * 1e-3);
        return m_a + m_b / l2 + m_c / (l2 * l2);
    }
    std::string describe() const override {
        std::ostringstream s;
        s << "Cauchy A = " << m_a << ", B = " << m_b << " um^2, C = " << m_c << " um^4";
        return s.str();
    }

private:
    double m_a, m_b, m_c;
};

class SellmeierIndex final : public IndexModel {
public:
    SellmeierIndex(std::vector<double> b, std::vector<double> c)
        : m_b(std::move(b)), m_c(std::move(c)) {}
    double n(double nm) const override {
        const double l2 = (nm * 1e-3) * (nm * 1e-3);
        double n2 = 1.0;
        for (size_t i = 0; i < m_b.size(); ++i) n2 += m_b[i] * l2 / (l2 - m_c[i]);
        return std::sqrt(std::max(n2, 0.0));
    }
    std::string describe() const override { return std::to_string(m_b.size()) + "-term Sellmeier"; }

private:
    std::vector<double> m_b, m_c;
};

IndexModelPtr with_range(std::shared_ptr<IndexModel> m, double min_nm, double max_nm) {
    m->min_nm = min_nm;
    m->max_nm = max_nm;
    return m;
}

}  // namespace

std::shared_ptr<IndexModel> constant_index(double n) { return std::make_shared<ConstantIndex>(n); }
std::shared_ptr<IndexModel> cauchy_index(double a, double b, double c) {
    return std::make_shared<CauchyIndex>(a, b, c);
}
std::shared_ptr<IndexModel> sellmeier_index(std::vector<double> b, std::vector<double> c) {
    return std::make_shared<SellmeierIndex>(std::move(b), std::move(c));
}

std::shared_ptr<IndexModel> abbe_index(double n_d, double v_d) {
    // n = A + B / l^2 with n(d) = n_d and n(F) - n(C) = (n_d - 1) / V_d.
    const double ld = kLineD * 1e-3, lf = kLineF * 1e-3, lc = kLineC * 1e-3;
    const double b = (n_d - 1.0) / v_d / (1.0 / (lf * lf) - 1.0 / (lc * lc));
    return cauchy_index(n_d - b / (ld * ld), b, 0.0);
}

const std::vector<Glass>& glass_catalogue() {
    static const std::vector<Glass> catalogue = [] {
        std::vector<Glass> g;
        // SCHOTT optical glass data sheets (Sellmeier B1..B3, C1..C3; n_d, V_d; range).
        g.push_back({"N-BK7", "borosilicate crown, the standard lens glass",
                     "SCHOTT data sheet N-BK7 (517642.251)",
                     with_range(sellmeier_index({1.03961212, 0.231792344, 1.01046945},
                                                {0.00600069867, 0.0200179144, 103.560653}),
                                300, 2500),
                     1.51680, 64.17});
        g.push_back({"N-SF11", "dense flint, high index", "SCHOTT data sheet N-SF11 (785257.322)",
                     with_range(sellmeier_index({1.73759695, 0.313747346, 1.89878101},
                                                {0.013188707, 0.0623068142, 155.23629}),
                                370, 2500),
                     1.78472, 25.68});
        g.push_back({"F2", "flint, classic achromat partner of crown",
                     "SCHOTT data sheet F2 (620364.360)",
                     with_range(sellmeier_index({1.34533359, 0.209073176, 0.937357162},
                                                {0.00997743871, 0.0470450767, 111.886764}),
                                320, 2500),
                     1.62004, 36.37});
        g.push_back({"N-SF6", "dense flint, strong dispersion (prisms)",
                     "SCHOTT data sheet N-SF6 (805254.337)",
                     with_range(sellmeier_index({1.77931763, 0.338149866, 2.08734474},
                                                {0.0133714182, 0.0617533621, 174.01759}),
                                370, 2500),
                     1.80518, 25.36});
        // The flint of Thorlabs' visible achromats (AC254-100-A: N-BK7 + SF5).
        g.push_back({"SF5", "flint, achromat partner of N-BK7",
                     "SCHOTT data sheet SF5 (673322.407)",
                     with_range(sellmeier_index({1.46141885, 0.247713019, 0.949995832},
                                                {0.0111826126, 0.0508594669, 112.041888}),
                                370, 2500),
                     1.67270, 32.21});
        g.push_back({"N-FK51A", "fluor crown, low dispersion (apochromats)",
                     "SCHOTT data sheet N-FK51A (487845.368)",
                     with_range(sellmeier_index({0.971247817, 0.216901417, 0.904651666},
                                                {0.00472301995, 0.0153575612, 168.68133}),
                                290, 2500),
                     1.48656, 84.47});
        // I. H. Malitson, "Interspecimen comparison of the refractive index of fused silica",
        // J. Opt. Soc. Am. 55, 1205 (1965): Sellmeier with C_i = (0.0684043, 0.1162414,
        // 9.896161 um)^2, 0.21 to 3.71 um; n_d 1.45846, V_d 67.82 as tabulated there. Kept as
        // it is, relative to air: the makers' air-relative data agree with it (Corning 7980,
        // Heraeus Suprasil: n_d 1.4585; Crystran 1.45804 at 600 nm), and a vacuum-to-air
        // conversion would move n_d by -4e-4, away from them.
        g.push_back({"fused-silica", "fused silica (SiO2 glass)", "Malitson, JOSA 55, 1205 (1965)",
                     with_range(sellmeier_index({0.6961663, 0.4079426, 0.8974794},
                                                {0.0684043 * 0.0684043, 0.1162414 * 0.1162414,
                                                 9.896161 * 9.896161}),
                                210, 3710),
                     1.45846, 67.82});
        // M. Daimon, A. Masumura, "Measurement of the refractive index of distilled water
        // from the near-infrared region to the ultraviolet region", Appl. Opt. 46, 3811
        // (2007), four-term Sellmeier at 20 degC, 0.182 to 1.129 um. Their index is absolute
        // (against vacuum, at vacuum wavelengths): converted to standard air like every other
        // material (air_index.h). Reference values: n_D = 1.33299 at 20 degC relative to air
        // (Tilton & Taylor, J. Res. NBS 20, 419 (1938), the refractometers' calibration
        // value); V_d about 55.8.
        g.push_back(
            {"water", "distilled water at 20 degC",
             "Daimon & Masumura, Appl. Opt. 46, 3811 (2007), converted to air",
             relative_to_air(with_range(
                 sellmeier_index({5.684027565e-1, 1.726177391e-1, 2.086189578e-2, 1.130748688e-1},
                                 {5.101829712e-3, 1.821153936e-2, 2.620722293e-2, 1.069792721e1}),
                 182, 1129)),
             1.3330, 55.8});
        // F. Peter, "Uber Brechungsindizes und Absorptionskonstanten des Diamanten zwischen
        // 644 und 226 mu", Z. Phys. 15, 358 (1923): n^2 = 1 + 0.3306 l^2/(l^2 - 0.175^2)
        // + 4.3356 l^2/(l^2 - 0.106^2); n_d = 2.4175, V_d = 55.3 (gemmological tables).
        g.push_back({"diamond", "diamond (C)", "Peter, Z. Phys. 15, 358 (1923)",
                     with_range(sellmeier_index({0.3306, 4.3356}, {0.175 * 0.175, 0.106 * 0.106}),
                                225, 2500),
                     2.4175, 55.3});
        // Optical plastics are specified by their catalogue code (n_d, V_d); e.g. Evonik
        // PLEXIGLAS (PMMA) n_d 1.4918, V_d 57.2 and Covestro Makrolon (polycarbonate)
        // n_d 1.5855, V_d 29.9 optical-grade data. Modelled by a two-term Cauchy through the d,
        // F and C lines: exact there, an approximation towards the ends of the visible.
        g.push_back({"PMMA", "acrylic (PMMA), moulded lenses",
                     "optical-grade PMMA: n_d 1.4918, V_d 57.2",
                     with_range(abbe_index(1.4918, 57.2), 360, 1100), 1.4918, 57.2});
        g.push_back({"polycarbonate", "polycarbonate (PC), moulded lenses",
                     "optical-grade PC: n_d 1.5855, V_d 29.9",
                     with_range(abbe_index(1.5855, 29.9), 360, 1100), 1.5855, 29.9});
        return g;
    }();
    return catalogue;
}

}  // namespace lenslab
