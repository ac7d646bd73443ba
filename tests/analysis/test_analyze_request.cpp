// The bench's request in the library (analysis/analyze_request.h): the document it gives is
// the report's JSON plus what was asked for, and options that do not fit are refused with
// the command line's words.

#include <gtest/gtest.h>

#include "analysis/analyze_request.h"
#include "lens_scene_builder.h"

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
