// The spectral data `lenslab spectra` prints, against the published tables: CIE 1931 2-degree
// colour-matching functions and CIE D65 (CIE 15:2004, tables T.1 and T.4, 5 nm steps), and
// Planck's law for a blackbody.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "optics/air_index.h"
#include "optics/spectral_table.h"
#include "optics/spectrum.h"

namespace lenslab {
namespace {

TEST(SpectralTable, RowsHoldTheCieTablesAndTheAirIndex) {
    const std::vector<SpectralRow> rows = spectral_rows({500, 550, 560}, 2856);
    ASSERT_EQ(rows.size(), 3u);
    // CIE 1931 (to the table's 6 decimals): 500 nm 0.004900 0.323000 0.272000; 550 nm 0.433450
    // 0.994950 0.008750.
    EXPECT_NEAR(rows[0].cmf.x, 0.0049, 5e-7);
    EXPECT_NEAR(rows[0].cmf.y, 0.323, 5e-7);
    EXPECT_NEAR(rows[0].cmf.z, 0.272, 5e-7);
    EXPECT_NEAR(rows[1].cmf.x, 0.43345, 5e-7);
    EXPECT_NEAR(rows[1].cmf.y, 0.99495, 5e-7);
    EXPECT_NEAR(rows[1].cmf.z, 0.00875, 5e-7);
    // D65 relative spectral power: 109.354 at 500 nm, 104.046 at 550, 100 at 560.
    EXPECT_NEAR(rows[0].d65, 1.09354, 1e-6);
    EXPECT_NEAR(rows[1].d65, 1.04046, 1e-6);
    EXPECT_DOUBLE_EQ(rows[2].d65, 1.0);
    // Planck: B(500) / B(560) = (560/500)^5 (e^(c2/560 T) - 1) / (e^(c2/500 T) - 1).
    const double c2 = 6.62607015e-34 * 299792458.0 / 1.380649e-23;  // m K
    const double expected = std::pow(560.0 / 500.0, 5) * std::expm1(c2 / (560e-9 * 2856)) /
                            std::expm1(c2 / (500e-9 * 2856));
    EXPECT_NEAR(rows[0].blackbody, expected, 1e-6 * expected);
    EXPECT_EQ(rows[1].air_index, standard_air_index(550));
    EXPECT_NEAR(rows[1].air_index, 1.000273, 2e-6);
}

// CIE illuminant A's published relative spectral power (CIE 15:2004 Table T.1, 100 at 560 nm).
TEST(SpectralTable, IlluminantAMatchesTheCieTable) {
    const std::vector<SpectralRow> rows = spectral_rows({400, 500, 600, 700});
    const double published[] = {14.7080, 59.8611, 129.043, 198.261};
    for (size_t i = 0; i < rows.size(); ++i)
        EXPECT_NEAR(rows[i].illuminant_a * 100, published[i], 5e-5 * published[i]) << rows[i].nm;
}

// Each named light spectrum has its illuminant's chromaticity (CIE 15:2004 Table T.3, 2-degree
// observer): A (0.44757, 0.40745), D65 (0.31272, 0.32903), E (1/3, 1/3); the sums over the
// 1 nm grid of the 5 nm colour-matching tables agree to a few 1e-4.
TEST(SpectralTable, NamedSpectraHaveTheirIlluminantsChromaticity) {
    const std::map<std::string, std::pair<double, double>> published{
        {"illuminant_a", {0.44757, 0.40745}},
        {"d65", {0.31272, 0.32903}},
        {"equal_energy", {1.0 / 3, 1.0 / 3}}};
    ASSERT_EQ(named_spectra().size(), published.size());
    for (const NamedSpectrum& named : named_spectra()) {
        const SpectrumPtr s = named.make();
        Vec3 xyz{0, 0, 0};
        for (double nm = kLambdaMinNm; nm <= kLambdaMaxNm; nm += 1)
            xyz += cie_xyz_bar(nm) * s->eval(nm);
        const double sum = xyz.x + xyz.y + xyz.z;
        const auto [x, y] = published.at(named.name);
        EXPECT_NEAR(xyz.x / sum, x, 3e-4) << named.name;
        EXPECT_NEAR(xyz.y / sum, y, 3e-4) << named.name;
    }
}

TEST(SpectralTable, ValuesOutOfRangeAreRefused) {
    EXPECT_THROW(spectral_rows({359}), std::invalid_argument);
    EXPECT_THROW(spectral_rows({831}), std::invalid_argument);
    EXPECT_THROW(spectral_rows({550}, 100), std::invalid_argument);
    EXPECT_EQ(spectral_rows({550}).at(0).blackbody, 0.0);  // none asked for
}

TEST(SpectralTable, WavelengthListsAndRanges) {
    EXPECT_EQ(parse_wavelength_list("486.1327,587.5618"),
              (std::vector<double>{486.1327, 587.5618}));
    EXPECT_EQ(parse_wavelength_list("400:500:50"), (std::vector<double>{400, 450, 500}));
    EXPECT_EQ(parse_wavelength_list("400:520:50"), (std::vector<double>{400, 450, 500}));
    EXPECT_EQ(parse_wavelength_list("550"), (std::vector<double>{550}));
    for (const char* bad : {"", "5x0", "400:500", "500:400:10", "400:500:0", "1,,2"})
        EXPECT_THROW(parse_wavelength_list(bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace lenslab
