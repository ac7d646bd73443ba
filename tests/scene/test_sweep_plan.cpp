// A sweep's plan: parsing POINTER=FROM:TO:COUNT, the value of each frame, the frame's JSON,
// the messages for what is wrong, and the split of the frames across a cluster's ranks.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "scene/sweep_plan.h"

namespace lenslab {
namespace {

// The message `sets` (then `scene`, when given) is refused with.
std::string sweep_plan_error(const std::vector<std::string>& sets,
                             const nlohmann::json& scene = nullptr) {
    try {
        const SweepPlan plan = parse_sweep_plan(sets);
        if (!scene.is_null()) check_sweep_targets(scene, plan);
    } catch (const SweepError& e) {
        return e.what();
    }
    return "";
}

const nlohmann::json kSweepScene = nlohmann::json::parse(R"({
    "render": {"width": 64, "spp": 4},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass"},
                {"type": "lens", "center": [0, 0, 2.5], "front": {"radius": 10}}]})");

TEST(SweepPlan, ParsesPointerAndRange) {
    const SweepParameter p = parse_sweep_parameter("/objects/1/center/2=-1.5:2.5e0:5");
    EXPECT_EQ(p.pointer, "/objects/1/center/2");
    EXPECT_EQ(p.from, -1.5);
    EXPECT_EQ(p.to, 2.5);
    EXPECT_EQ(p.count, 5);
}

TEST(SweepPlan, ValuesRunLinearlyAndHitBothEndsExactly) {
    const SweepParameter p = parse_sweep_parameter("/a=0.1:0.7:7");
    EXPECT_EQ(sweep_value(p, 0), 0.1);
    EXPECT_EQ(sweep_value(p, 6), 0.7);
    for (int i = 0; i < 7; ++i) EXPECT_NEAR(sweep_value(p, i), 0.1 + 0.1 * i, 1e-15);
    const SweepParameter down = parse_sweep_parameter("/a=5:0:3");
    EXPECT_EQ(sweep_value(down, 1), 2.5);
    EXPECT_EQ(sweep_value(down, 2), 0.0);
}

TEST(SweepPlan, CountOneIsFrom) {
    const SweepParameter p = parse_sweep_parameter("/a=3:9:1");
    EXPECT_EQ(p.count, 1);
    EXPECT_EQ(sweep_value(p, 0), 3.0);
}

TEST(SweepPlan, BadTextIsRefusedNamingThePart) {
    const auto refused = [](const std::string& text, const std::string& part) {
        const std::string message = sweep_plan_error({text});
        EXPECT_NE(message.find(part), std::string::npos) << text << " -> " << message;
    };
    refused("/a", "no '=' between the pointer and the range");
    refused("a/b=0:1:2", "'a/b' is not a JSON pointer into the scene (it starts with '/')");
    refused("/a~2=0:1:2", "'/a~2' is not a JSON pointer");
    refused("/a=0:1", "the range '0:1' is not FROM:TO:COUNT");
    refused("/a=0:1:2:3", "the range '0:1:2:3' is not FROM:TO:COUNT");
    refused("/a=x:1:2", "FROM 'x' is not a finite number");
    refused("/a=0:inf:2", "TO 'inf' is not a finite number");
    refused("/a=0:1:0", "COUNT '0' is not a whole number from 1 to 100000");
    refused("/a=0:1:2.5", "COUNT '2.5' is not a whole number");
    refused("/a=0:1:", "COUNT '' is not a whole number");
    EXPECT_EQ(sweep_plan_error({}), "--set: nothing to sweep (give POINTER=FROM:TO:COUNT)");
}

TEST(SweepPlan, SeveralParametersZipAndMustAgreeOnTheCount) {
    const SweepPlan plan = parse_sweep_plan({"/a=0:1:3", "/b=10:20:3"});
    EXPECT_EQ(plan.count, 3);
    ASSERT_EQ(plan.parameters.size(), 2u);
    EXPECT_EQ(sweep_plan_error({"/a=0:1:3", "/b=0:1:4"}),
              "--set: /b has 4 frames but /a has 3 (the parameters change together, so their "
              "COUNTs must agree)");
    EXPECT_EQ(sweep_plan_error({"/a=0:1:3", "/a=0:2:3"}), "--set: /a is swept twice");
}

TEST(SweepPlan, TargetsMustBeNumbersThatExist) {
    EXPECT_EQ(sweep_plan_error({"/objects/1/center/2=0:1:2"}, kSweepScene), "");
    EXPECT_EQ(sweep_plan_error({"/objects/5/center/2=0:1:2"}, kSweepScene),
              "--set /objects/5/center/2: the scene has nothing at /objects/5 (/objects holds 2 "
              "elements, 0 to 1)");
    EXPECT_EQ(sweep_plan_error({"/objects/1/centre/2=0:1:2"}, kSweepScene),
              "--set /objects/1/centre/2: the scene has nothing at /objects/1/centre");
    EXPECT_EQ(sweep_plan_error({"/camera/fov=0:1:2"}, kSweepScene),
              "--set /camera/fov: the scene has nothing at /camera");
    EXPECT_EQ(sweep_plan_error({"/objects/0/material=0:1:2"}, kSweepScene),
              "--set /objects/0/material: the scene has \"glass\" there, not a number");
    EXPECT_EQ(sweep_plan_error({"/objects/1/center=0:1:2"}, kSweepScene),
              "--set /objects/1/center: the scene has [0, 0, 2.5] there, not a number");
    const std::string through_number = sweep_plan_error({"/objects/0/radius/x=0:1:2"}, kSweepScene);
    EXPECT_NE(through_number.find("/objects/0/radius is 1"), std::string::npos) << through_number;
}

TEST(SweepPlan, FrameJsonHoldsTheFramesValues) {
    const SweepPlan plan = parse_sweep_plan({"/objects/1/center/2=1:2:3", "/render/width=32:96:3"});
    check_sweep_targets(kSweepScene, plan);
    const nlohmann::json frame = sweep_frame_json(kSweepScene, plan, 1);
    EXPECT_EQ(frame["objects"][1]["center"][2].get<double>(), 1.5);
    // A whole number stays a whole number where the file had one.
    EXPECT_TRUE(frame["render"]["width"].is_number_integer());
    EXPECT_EQ(frame["render"]["width"].get<int>(), 64);
    EXPECT_EQ(frame["objects"][0], kSweepScene["objects"][0]);
    const SweepPlan half = parse_sweep_plan({"/render/width=1:2:3"});
    EXPECT_EQ(sweep_frame_json(kSweepScene, half, 1)["render"]["width"].get<double>(), 1.5);
}

TEST(SweepPlan, FramesForRankCoverEveryFrameOnce) {
    for (int size = 1; size <= 4; ++size) {
        for (int count : {0, 1, 2, 3, 6, 7, 100}) {
            std::vector<int> seen(count, 0);
            for (int rank = 0; rank < size; ++rank) {
                const std::vector<int> frames = frames_for_rank(count, rank, size);
                EXPECT_TRUE(std::is_sorted(frames.begin(), frames.end()));
                // Round-robin: no rank has more than one frame more than another.
                EXPECT_LE(frames.size(), static_cast<size_t>((count + size - 1) / size));
                EXPECT_GE(frames.size(), static_cast<size_t>(count / size));
                for (int frame : frames) {
                    ASSERT_GE(frame, 0);
                    ASSERT_LT(frame, count);
                    ++seen[frame];
                }
            }
            for (int frame = 0; frame < count; ++frame)
                EXPECT_EQ(seen[frame], 1)
                    << "frame " << frame << " of " << count << ", size " << size;
        }
    }
    EXPECT_EQ(frames_for_rank(7, 1, 3), (std::vector<int>{1, 4}));
    EXPECT_THROW(frames_for_rank(3, 2, 2), std::invalid_argument);
}

TEST(SweepPlan, FrameStemsSortInFrameOrder) {
    EXPECT_EQ(frame_stem(0), "00000");
    EXPECT_EQ(frame_stem(42), "00042");
}

}  // namespace
}  // namespace lenslab
