// The table of a sweep --analyze (analysis/report/sweep_table.h): which figures become columns, and
// the CSV and sweep.json built from them.

#include <gtest/gtest.h>

#include "analysis/report/sweep_table.h"

namespace lenslab {
namespace {

using nlohmann::ordered_json;

ordered_json table_report(double efl, bool with_chief) {
    ordered_json j;
    j["wavelength_nm"] = 587.5618;
    j["length_unit"] = "mm";
    j["efl"] = efl;
    j["rays"] = 817;
    j["principal_planes"] = {{"front", 0.5}, {"note", "text"}};
    j["lsa"] = ordered_json::array({1, 2});
    if (with_chief) j["first_order"] = {{"f_number", 4.0}, {"real_chief_ray", {{"y", 1}}}};
    return j;
}

TEST(SweepTable, FiguresAreTheTopLevelNumbersAndThoseOneLevelDown) {
    const auto figures = bench_figures(table_report(50, true));
    std::vector<std::string> names;
    for (const auto& [name, value] : figures) names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"wavelength_nm", "efl", "rays",
                                               "principal_planes.front", "first_order.f_number"}));
}

TEST(SweepTable, CsvHasARowPerFrameAndEmptyCellsForMissingFigures) {
    const SweepPlan plan = parse_sweep_plan({"/objects/0/front/radius=20:40:2"});
    const std::string csv = sweep_csv(plan, {table_report(38.7, false), table_report(77.4, true)});
    EXPECT_EQ(csv,
              "frame,/objects/0/front/radius,wavelength_nm,efl,rays,principal_planes.front,"
              "first_order.f_number\n"
              "0,20.0,587.5618,38.7,817,0.5,\n"
              "1,40.0,587.5618,77.4,817,0.5,4.0\n");
}

TEST(SweepTable, SummaryListsFramesValuesAndFigures) {
    const SweepPlan plan = parse_sweep_plan({"/a=0:1:2", "/b=5:3:2"});
    const ordered_json j =
        sweep_summary_json(plan, "s.json", {"frames/00000.json", "frames/00001.json"},
                           {table_report(1, false), table_report(2, false)});
    EXPECT_EQ(j["scene"], "s.json");
    EXPECT_EQ(j["count"], 2);
    EXPECT_EQ(j["parameters"][1]["pointer"], "/b");
    EXPECT_EQ(j["frames"][1]["file"], "frames/00001.json");
    EXPECT_EQ(j["frames"][1]["values"]["/b"], 3.0);
    EXPECT_EQ(j["frames"][1]["figures"]["efl"], 2);
    const ordered_json rendered =
        sweep_summary_json(plan, "s.json", {"frames/00000.png", "frames/00001.png"});
    EXPECT_FALSE(rendered["frames"][0].contains("figures"));
}

}  // namespace
}  // namespace lenslab
