// The bench's request in the library (analysis/report/analyze_request.h): the document it gives is
// the report's JSON plus what was asked for, and options that do not fit are refused with
// the command line's words.

#include <gtest/gtest.h>

#include "../lens_scene_builder.h"
#include "analysis/report/analyze_request.h"

namespace lenslab {
namespace {

const test::LensSpec kRequestLens{
    "LA1131", 0, 5.34, 25.4, test::sphere(25.75), test::sphere(0), test::glass("N-BK7")};

std::string analyze_request_error(const AnalyzeRequest& request) {
    try {
        (void)analyze_report(test::lens_scene({kRequestLens}), request);
    } catch (const AnalyzeRequestError& e) {
        return e.what();
    }
    return "";
}

TEST(AnalyzeRequest, DocumentIsTheReportWithWhatWasAskedFor) {
    const Scene scene = test::lens_scene({kRequestLens});
    const nlohmann::ordered_json plain = analyze_report(scene, {});
    const OpticalSystem system = build_optical_system(scene);
    EXPECT_EQ(plain, report_json(system, analyze_lens_system(system, {})));
    EXPECT_FALSE(plain.contains("scene"));  // no file named

    AnalyzeRequest request;
    request.spots = true;
    request.psf = true;
    const nlohmann::ordered_json asked = analyze_report(scene, request, "lens.json");
    EXPECT_EQ(asked["scene"], "lens.json");
    EXPECT_TRUE(asked.contains("spots"));
    EXPECT_TRUE(asked.contains("psf"));
    EXPECT_FALSE(asked.contains("mtf"));
    EXPECT_DOUBLE_EQ(asked["efl"].get<double>(), plain["efl"].get<double>());
}

TEST(AnalyzeRequest, ReportKeysGiveTheWholeDocumentsValuesAlone) {
    const Scene scene = test::lens_scene({kRequestLens});
    AnalyzeRequest request;
    request.spots = true;
    const nlohmann::ordered_json whole = analyze_report(scene, request, "lens.json");
    const AnalyzeResults results = analyze_scene(scene, request, "lens.json");
    EXPECT_EQ(analyze_json_keys(results, request, "lens.json").size(), whole.size());
    // Each key alone, and two together, each computing only what it needs.
    for (const auto& item : whole.items()) {
        request.report_keys = {item.key()};
        const nlohmann::ordered_json one = analyze_report(scene, request, "lens.json");
        ASSERT_EQ(one.size(), 1u) << item.key();
        EXPECT_EQ(one[item.key()], item.value()) << item.key();
    }
    request.report_keys = {"rms_spot_best", "efl", "no_such_key"};
    const nlohmann::ordered_json two = analyze_report(scene, request, "lens.json");
    EXPECT_EQ(two, (nlohmann::ordered_json{{"efl", whole["efl"]},
                                           {"rms_spot_best", whole["rms_spot_best"]}}));
    EXPECT_FALSE(report_parts({"efl"}).beam);
    EXPECT_TRUE(report_parts({"rms_spot_best"}).beam);
    EXPECT_FALSE(report_parts({"rms_spot_best"}).seidel);
    EXPECT_FALSE(report_parts({"rms_spot_best"}).paraxial_spot);
    EXPECT_TRUE(report_parts({"rms_spot_paraxial"}).paraxial_spot);
}

TEST(AnalyzeRequest, OptionsThatDoNotFitAreRefused) {
    AnalyzeRequest stop;
    stop.stop = 3;
    EXPECT_EQ(analyze_request_error(stop), "--stop 3: the system has 2 surfaces, numbered 1 to 2");
    AnalyzeRequest field;
    field.fields = {95};
    EXPECT_EQ(analyze_request_error(field),
              "--fields: 95 degrees is not a field angle (between -90 and 90)");
    AnalyzeRequest band;
    band.band = {450, 700};
    EXPECT_EQ(analyze_request_error(band),
              "--band: it sets the band of --focal-shift, which was not asked for");
    AnalyzeRequest lens;
    lens.lens = "L9";
    EXPECT_NE(analyze_request_error(lens).find("--lens: no lens named 'L9' in the scene"),
              std::string::npos)
        << analyze_request_error(lens);
}

}  // namespace
}  // namespace lenslab
