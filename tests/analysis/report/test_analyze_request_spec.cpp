// The analysis request's declarations (analysis/report/analyze_request_spec.h): one list from
// which the command line's options are made and Python's keywords are checked; here held to
// the request they fill and to the options table of docs/optical-bench.md, so a new option
// that is not documented (or a documented one that is gone) fails.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "analysis/report/analyze_request_spec.h"

namespace lenslab {
namespace {

using nlohmann::json;

// The options documented in the table of `lenslab analyze`'s options: rows "| `--name ...".
std::map<std::string, std::string> documented_analyze_options() {
    std::ifstream in(std::string(LENSLAB_SOURCE_DIR) + "/docs/optical-bench.md");
    std::stringstream text;
    text << in.rdbuf();
    std::map<std::string, std::string> rows;
    static const std::regex row(R"(^\| `--([a-z-]+)[^`]*` \|(.*)$)");
    std::string line;
    while (std::getline(text, line)) {
        std::smatch m;
        if (std::regex_match(line, m, row)) rows[m[1]] = m[2];
    }
    return rows;
}

TEST(AnalyzeRequestSpec, TheDocsTableListsExactlyTheCommandLinesOptions) {
    const std::map<std::string, std::string> documented = documented_analyze_options();
    std::set<std::string> declared;
    for (const RequestOption& o : analyze_request_options()) {
        if (o.where == RequestWhere::Python) continue;
        declared.insert(o.name);
        ASSERT_TRUE(documented.contains(o.name)) << "--" << o.name << " is not in the table";
        // A whole number's row gives its range as the command line checks it.
        if (o.value == RequestValue::Whole) {
            EXPECT_NE(
                documented.at(o.name).find(std::to_string(o.low) + " to " + std::to_string(o.high)),
                std::string::npos)
                << "--" << o.name;
        }
    }
    for (const auto& [name, row] : documented)
        EXPECT_TRUE(declared.contains(name)) << "--" << name << " is documented, not declared";
}

TEST(AnalyzeRequestSpec, NamesAreUniqueAndTheirRelationsNameDeclaredOptions) {
    std::set<std::string> names;
    for (const RequestOption& o : analyze_request_options()) {
        EXPECT_TRUE(names.insert(o.name).second) << o.name;
        EXPECT_TRUE(o.set && o.get) << o.name;
        EXPECT_FALSE(o.help.empty()) << o.name;
        if (o.value == RequestValue::Whole) {
            EXPECT_LT(o.low, o.high) << o.name;
        }
        if (o.value == RequestValue::Choice) {
            EXPECT_GE(o.choices.size(), 2u) << o.name;
        }
    }
    for (const RequestOption& o : analyze_request_options()) {
        for (const std::string& other : o.excludes) EXPECT_TRUE(names.contains(other)) << other;
        if (!o.needs.empty()) {
            EXPECT_TRUE(names.contains(o.needs)) << o.needs;
        }
        EXPECT_EQ(o.excludes.empty(), o.excludes_why.empty()) << o.name;
    }
}

TEST(AnalyzeRequestSpec, PythonsKeywordsFillTheRequest) {
    const AnalyzeRequest r = analyze_request_from_json(json::parse(R"({
        "wavelength": 550, "stop": 3, "ray_aiming": "paraxial", "fields": [0, 14, 20],
        "spots": true, "rings": 3, "image_distance": -2.5, "field_map": 5,
        "report": ["efl"], "unit": "mm", "band": [450, 650]})"));
    EXPECT_EQ(r.wavelength_nm, 550);
    EXPECT_TRUE(r.wavelength_given);
    EXPECT_EQ(r.stop, 3);
    EXPECT_EQ(r.ray_aiming, RayAiming::Paraxial);
    EXPECT_EQ(r.fields, (std::vector<double>{0, 14, 20}));
    EXPECT_TRUE(r.spots);
    EXPECT_EQ(r.rings, 3);
    EXPECT_EQ(r.image_distance, -2.5);
    EXPECT_EQ(r.field_map, 5);
    EXPECT_EQ(r.report_keys, std::vector<std::string>{"efl"});
    EXPECT_EQ(r.unit, "mm");
    EXPECT_EQ(r.band, (std::vector<double>{450, 650}));
    // Not given: the request's defaults.
    EXPECT_FALSE(r.fans);
    EXPECT_EQ(r.fan_points, AnalyzeRequest{}.fan_points);
    EXPECT_FALSE(analyze_request_from_json(json::object()).wavelength_given);
}

TEST(AnalyzeRequestSpec, AKeyThatIsNoOptionOrOnlyTheCommandLinesIsRefused) {
    EXPECT_THROW((void)analyze_request_from_json(json{{"ring", 3}}), AnalyzeRequestError);
    // A figure file is the command line's; Python asks with Analysis.figure.
    EXPECT_THROW((void)analyze_request_from_json(json{{"spots_svg", "x.svg"}}),
                 AnalyzeRequestError);
}

TEST(AnalyzeRequestSpec, PythonsDefaultsAreTheRequestsOrNone) {
    const json options = analyze_request_options_json();
    std::map<std::string, json> defaults;
    for (const json& o : options) defaults[o["name"]] = o["default"];
    EXPECT_EQ(defaults.at("rings"), 6);
    EXPECT_EQ(defaults.at("spots"), false);
    EXPECT_EQ(defaults.at("field_map"), 0);
    EXPECT_TRUE(defaults.at("stop").is_null());  // 0 in the request: the lens file's stop
    EXPECT_TRUE(defaults.at("wavelength").is_null());
    EXPECT_FALSE(defaults.contains("json"));  // the command line's alone
    EXPECT_TRUE(defaults.contains("report"));
    for (const json& o : options) {
        if (o["name"] == "f_number") {
            EXPECT_EQ(o["option"], "--f-number");
            EXPECT_EQ(o["excludes"], (json{"aperture", "epd"}));
        }
    }
}

}  // namespace
}  // namespace lenslab
