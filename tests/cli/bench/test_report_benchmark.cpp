// `lenslab bench report`'s harness: the report's figures, the CSV, and a tiny run.

#include <gtest/gtest.h>

#include <string>

#include "bench/report_benchmark.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

TEST(ReportBenchmark, KnowsTheReportsFigures) {
    EXPECT_DOUBLE_EQ(report_build_seconds(100000), 1.794);
    EXPECT_DOUBLE_EQ(report_build_seconds(123), 0.0);
    EXPECT_DOUBLE_EQ(report_render_seconds(350000, 0.05), 25.423);
    EXPECT_DOUBLE_EQ(report_render_seconds(350000, 0.051), 0.0);
}

TEST(ReportBenchmark, WritesOneCsvRowPerPhotonsAndRadius) {
    ReportBenchmarkResult r;
    r.builds = {{100000, 1.0, 0.5, 1000}};
    r.renders = {{100000, 0.025, 2.0}, {100000, 0.05, 3.0}};
    const std::string csv = report_benchmark_csv(r);
    EXPECT_EQ(csv.rfind("photons,radius,trace_s,build_s,render_s,total_s,", 0), 0u);
    EXPECT_NE(csv.find("\n100000,0.025,1.0000,0.5000,2.0000,3.5000,1.794,9.264,"),
              std::string::npos)
        << csv;
    EXPECT_NE(csv.find("\n100000,0.050,1.0000,0.5000,3.0000,4.5000,1.794,12.602,"),
              std::string::npos)
        << csv;
}

TEST(ReportBenchmark, RunsOnATinyImage) {
    ReportBenchmarkSettings s;
    s.photons = {2000, 4000};
    s.radii = {0.05};
    s.width = s.height = 8;
    s.repeats = 1;
    s.threads = 1;
    s.thumbnail = 4;
    int lines = 0;
    const ReportBenchmarkResult r =
        run_report_benchmark(default_scene(), s, [&](const std::string&) { ++lines; });
    ASSERT_EQ(r.builds.size(), 2u);
    ASSERT_EQ(r.renders.size(), 2u);
    EXPECT_GT(r.builds[1].stored, r.builds[0].stored);
    EXPECT_EQ(r.grid.width(), 8);
    EXPECT_EQ(r.grid.height(), 4);
    EXPECT_EQ(lines, 4);
}

}  // namespace
}  // namespace lenslab
