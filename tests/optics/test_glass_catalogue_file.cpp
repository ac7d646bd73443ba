// A maker's catalogue file: what a good one gives, and the one clear error a malformed one
// gets (the file, the entry and why).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "optics/glass_catalogue_file.h"

namespace lenslab {
namespace {

std::string write_catalogue_file(const std::string& stem, const std::string& text) {
    const auto dir = std::filesystem::temp_directory_path() / "lenslab_glass_file_test";
    std::filesystem::create_directories(dir);
    const auto path = dir / (stem + ".json");
    std::ofstream(path) << text;
    return path.string();
}

std::string catalogue_file_error(const std::string& stem, const std::string& text) {
    const std::string path = write_catalogue_file(stem, text);
    try {
        read_glass_catalogue(path);
    } catch (const GlassDataError& e) {
        const std::string message = e.what();
        // Every message starts with the file's path; the tests compare what follows it.
        EXPECT_EQ(message.rfind(path, 0), 0u) << message;
        return message.substr(path.size());
    }
    return "no error";
}

const char* const kCatalogueHead = R"({"maker": "ACME", "references": ["ACME 2024"], "glasses": [)";

TEST(GlassCatalogueFile, ReadsAGlass) {
    const std::string path = write_catalogue_file(
        "good", std::string(kCatalogueHead) +
                    R"({"name":"K7","group":"optical","formula":2,"coefficients":[0,1.03961212,
            0.00600069867,0.231792344,0.0200179144,1.01046945,103.560653],"range_um":[0.3,2.5],
            "n_d":1.5168,"V_d":64.17,"code":"517642","ref":0,"k":[[0.4,1e-8],[0.5,9e-9]]},
            {"name":"T1","formula":"tabulated","n":[[0.4,1.53],[0.8,1.51]]}]})");
    const std::vector<Glass> glasses = read_glass_catalogue(path);
    ASSERT_EQ(glasses.size(), 2u);
    EXPECT_EQ(glasses[0].name, "K7");
    EXPECT_EQ(glasses[0].maker, "ACME");
    EXPECT_EQ(glasses[0].description, "ACME optical glass, code 517642");
    EXPECT_EQ(glasses[0].source, "refractiveindex.info (CC0): ACME 2024");
    EXPECT_NEAR(glasses[0].model->n_d(), 1.5168, 5e-6);
    EXPECT_EQ(glasses[0].datasheet_v_d, 64.17);
    ASSERT_EQ(glasses[0].k_um.size(), 2u);
    EXPECT_EQ(glasses[0].k_um[1].second, 9e-9);
    EXPECT_TRUE(std::isnan(glasses[1].datasheet_n_d));  // no catalogue values given
    EXPECT_NEAR(glasses[1].model->n(600), 1.52, 1e-12);
}

TEST(GlassCatalogueFile, MalformedFilesGetOneClearError) {
    const std::string head = kCatalogueHead;
    EXPECT_EQ(catalogue_file_error("not_json", "{\n  \"maker\": \"ACME\",\n  oops\n}"),
              ":3:3: not valid JSON");
    EXPECT_EQ(catalogue_file_error("no_maker", R"({"glasses": []})"),
              ": maker: missing (required)");
    EXPECT_EQ(catalogue_file_error("no_glasses", R"({"maker": "ACME"})"),
              ": glasses: missing (required, an array)");
    EXPECT_EQ(catalogue_file_error("odd_coefficients",
                                   head + R"({"name":"K7","formula":2,"coefficients":[0,1,0.01,2],
                                   "range_um":[0.3,2.5]}]})"),
              ": glasses[0] (K7).coefficients: Sellmeier-2 (formula 2) takes C1 and then pairs: an "
              "odd number, at least 3 coefficients, got 4");
    EXPECT_EQ(catalogue_file_error("bad_formula", head + R"({"name":"K7","formula":12,
                                   "coefficients":[0,1,0.01],"range_um":[0.3,2.5]}]})"),
              ": glasses[0] (K7).coefficients: formula 12 is not one of the database's formulas "
              "1-9");
    EXPECT_EQ(catalogue_file_error("no_range", head + R"({"name":"K7","formula":2,
                                   "coefficients":[0,1,0.01]}]})"),
              ": glasses[0] (K7).range_um: missing (required)");
    EXPECT_EQ(catalogue_file_error("nd_without_vd", head + R"({"name":"K7","formula":2,
                                   "coefficients":[0,1,0.01],"range_um":[0.3,2.5],"n_d":1.5}]})"),
              ": glasses[0] (K7).V_d: missing (required)");
    EXPECT_EQ(catalogue_file_error("bad_k", head + R"({"name":"K7","formula":2,
                                   "coefficients":[0,1,0.01],"range_um":[0.3,2.5],"k":[[0.4]]}]})"),
              ": glasses[0] (K7).k: row 1 must be a [wavelength um, value] pair of numbers");
    EXPECT_EQ(catalogue_file_error("bad_ref", head + R"({"name":"K7","formula":2,
                                   "coefficients":[0,1,0.01],"range_um":[0.3,2.5],"ref":3}]})"),
              ": glasses[0] (K7).ref: must index the file's references");
    EXPECT_EQ(catalogue_file_error("twice", head + R"({"name":"K7","formula":"tabulated",
                                   "n":[[0.4,1.5],[0.8,1.49]]},{"name":"k7","formula":"tabulated",
                                   "n":[[0.4,1.5],[0.8,1.49]]}]})"),
              ": glasses[1] (k7).name: given twice in this catalogue (also glasses[0])");
    EXPECT_EQ(catalogue_file_error("no_name", head + R"({"formula":2}]})"),
              ": glasses[0].name: missing (required)");
    EXPECT_EQ(catalogue_file_error("short_table", head + R"({"name":"T","formula":"tabulated",
                                   "n":[[0.5,1.5]]}]})"),
              ": glasses[0] (T).n: an index table needs at least two wavelengths, got 1");
}

TEST(GlassCatalogueFile, TheDataFolderIsFoundOrNamed) {
    // The build points at the source tree's data/glass; LENSLAB_GLASS_DATA overrides it, and a
    // wrong override is named rather than ignored.
    EXPECT_NO_THROW(glass_data_directory());
    ::setenv("LENSLAB_GLASS_DATA", "/nonexistent/glass", 1);
    try {
        glass_data_directory();
        ADD_FAILURE() << "a missing folder was accepted";
    } catch (const GlassDataError& e) {
        EXPECT_STREQ(e.what(),
                     "LENSLAB_GLASS_DATA=/nonexistent/glass: no schott.json there (it must name "
                     "the folder holding the glass catalogues)");
    }
    ::unsetenv("LENSLAB_GLASS_DATA");
}

}  // namespace
}  // namespace lenslab
