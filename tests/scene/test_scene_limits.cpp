// The limits of src/scene/limits.h that a small bad file cannot reach (tests/scene/bad holds
// the others): counts of objects and lights, file sizes, files that are not files, and the
// edges of the image and formula limits. Each refusal must come before the work it guards.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "math/formula.h"
#include "render/render_session.h"
#include "scene/json_reader.h"
#include "scene/limits.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

nlohmann::json minimal_scene() {
    return nlohmann::json::parse(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}})");
}

// The message scene_from_json gives for `root`, or "" if it was accepted.
std::string refusal(const nlohmann::json& root) {
    try {
        (void)scene_from_json(root);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

// A file of `bytes` bytes that takes no disk space (a hole), in the temp folder.
std::string sparse_file(const std::string& name, uint64_t bytes) {
    const fs::path path =
        fs::temp_directory_path() / ("lenslab_limits_" + std::to_string(getpid()) + "_" + name);
    { std::ofstream(path, std::ios::binary | std::ios::trunc); }
    fs::resize_file(path, bytes);
    return path.string();
}

TEST(SceneLimits, ObjectCountIsCheckedBeforeAnyObjectIsRead) {
    // The entries are nulls: had the reader looked at one, it would refuse that instead.
    nlohmann::json root = minimal_scene();
    root["objects"] = nlohmann::json::array();
    root["objects"].get_ref<nlohmann::json::array_t&>().resize(kMaxObjects + 1);
    EXPECT_EQ(refusal(root), "objects: holds 1000001 objects, more than the 1000000 allowed");
}

TEST(SceneLimits, LensGroupElementsCountAsObjects) {
    nlohmann::json group = {
        {"type", "lens_group"}, {"vertex", {0, 0, 0}}, {"axis", {0, 0, 1}}, {"diameter", 10}};
    group["elements"] = nlohmann::json::array();
    group["elements"].get_ref<nlohmann::json::array_t&>().resize(kMaxObjects + 1);
    nlohmann::json root = minimal_scene();
    root["objects"] = nlohmann::json::array({group});
    EXPECT_EQ(refusal(root),
              "objects[0].elements: holds 1000001 elements, more than the 1000000 allowed");
}

TEST(SceneLimits, LightCountIsCheckedBeforeAnyLightIsRead) {
    nlohmann::json root = minimal_scene();
    root["lights"] = nlohmann::json::array();
    root["lights"].get_ref<nlohmann::json::array_t&>().resize(kMaxLights + 1);
    EXPECT_EQ(refusal(root), "lights: holds 10001 lights, more than the 10000 allowed");
    // At the limit, the first light is read (and refused for being null).
    root["lights"].get_ref<nlohmann::json::array_t&>().resize(kMaxLights);
    EXPECT_EQ(refusal(root), "lights[0]: must be an object { \"type\": ... }");
}

TEST(SceneLimits, ImageSizeLimitIsOnThePixelCount) {
    EXPECT_FALSE(image_size_problem(8192, 8192));
    EXPECT_FALSE(image_size_problem(16384, 4096));
    EXPECT_EQ(image_size_problem(8192, 8193).value_or(""),
              "8192 x 8193 is 67117056 pixels, more than the 67108864 (8192 x 8192) allowed");
}

TEST(SceneLimits, RenderRefusesTooManyPixelsBeforeAllocatingTheFilm) {
    // What reaches the renderer from the command line or the editor, past the scene reader.
    RenderSettings s;
    s.width = 16384;
    s.height = 16384;
    try {
        check_image_resources(s);
        FAIL() << "a 16384 x 16384 image was accepted";
    } catch (const ResourceError& e) {
        EXPECT_STREQ(e.what(),
                     "image: 16384 x 16384 is 268435456 pixels, more than the 67108864 (8192 x "
                     "8192) allowed");
    }
    s.width = 64;
    s.height = 48;
    EXPECT_NO_THROW(check_image_resources(s));
}

TEST(SceneLimits, FormulaLengthLimit) {
    const std::string at_limit = "r^2" + std::string(Formula::kMaxLength - 3, ' ');
    EXPECT_NO_THROW(Formula(at_limit, {"r"}, ""));
    try {
        Formula(at_limit + " ", {"r"}, "");
        FAIL() << "a formula of 4097 characters was accepted";
    } catch (const FormulaError& e) {
        EXPECT_EQ(e.message(), "is 4097 characters long, more than the 4096 allowed");
    }
}

TEST(SceneLimits, SceneFileLargerThanTheLimitIsNotRead) {
    const std::string path = sparse_file("huge_scene.json", kMaxSceneFileBytes + 1);
    try {
        (void)load_scene_file(path);
        FAIL() << "a 256 MiB scene file was read";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), path);
        EXPECT_EQ(e.reason(),
                  "cannot read scene file: it is 256 MiB (268435457 bytes), more than the 256 MiB "
                  "allowed");
    }
    fs::remove(path);
}

TEST(SceneLimits, SceneFileThatIsADeviceIsNotRead) {
    // Reading /dev/zero would never end.
    try {
        (void)load_scene_file("/dev/zero");
        FAIL() << "/dev/zero was read as a scene";
    } catch (const SceneError& e) {
        EXPECT_STREQ(
            e.what(),
            "/dev/zero: cannot read scene file: it is not a regular file (a device or a pipe)");
    }
}

TEST(SceneLimits, ObjFileLargerThanTheLimitIsNotRead) {
    const std::string path = sparse_file("huge_mesh.obj", kMaxObjFileBytes + 1);
    nlohmann::json root = minimal_scene();
    root["objects"] = {{{"type", "mesh"}, {"file", path}, {"material", {{"color", 0.5}}}}};
    EXPECT_EQ(refusal(root), "objects[0].file: cannot read '" + path +
                                 "': is 512 MiB (536870913 bytes), more than the 512 MiB allowed");
    fs::remove(path);
}

// A value nested `depth` levels deep, {"a": {"a": ... 1}}, built without recursion.
nlohmann::json deep_object(int depth) {
    nlohmann::json root = 1;
    for (int i = 0; i < depth; ++i) root = nlohmann::json{{"a", std::move(root)}};
    return root;
}

TEST(SceneLimits, ExcerptOfInputIsShortAndFlatHoweverDeep) {
    const nlohmann::json deep = deep_object(100000);
    EXPECT_EQ(excerpt(deep), R"({"a": {...}})");
    EXPECT_EQ(excerpt(nlohmann::json::array({1, nlohmann::json::array({2}), "x"})),
              R"([1, [...], "x"])");
    const std::string long_text = excerpt(nlohmann::json(std::string(1000, 'z')));
    EXPECT_LE(long_text.size(), 60u);
    EXPECT_EQ(long_text.substr(long_text.size() - 3), "...");
    EXPECT_EQ(excerpt(nlohmann::json(std::string("a\x1b[31m"))), R"("a\u001b[31m")");
}

TEST(SceneLimits, MeshFaceHoldingADeepValueIsRefusedWithAnExcerpt) {
    // The message once quoted the face with dump(), whose recursion overflowed the stack.
    nlohmann::json root = minimal_scene();
    root["objects"] = {{{"type", "mesh"},
                        {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                        {"faces", nlohmann::json::array()},
                        {"material", {{"color", 0.5}}}}};
    root["objects"][0]["faces"].push_back(deep_object(100000));
    EXPECT_EQ(
        refusal(root),
        R"(objects[0].faces[0]: a face must be an array of at least 3 vertex indices, got {"a": {...}})");
}

// The message parse_json_strict gives for `text`, or "" if it was accepted.
std::string json_refusal(const std::string& text) {
    try {
        (void)parse_json_strict(text, "s.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(SceneLimits, JsonNestingDeeperThanTheLimitIsRefusedWithItsPosition) {
    const std::string ok = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
    EXPECT_EQ(json_refusal(ok), "");
    EXPECT_EQ(json_refusal("{\"a\":\n" + std::string(100000, '[') + std::string(100000, ']') + "}"),
              "s.json: invalid JSON: arrays and objects nested more than 512 deep, at line 2, "
              "column 512 (byte 518)");
    // Brackets inside strings do not count.
    EXPECT_EQ(json_refusal("[\"[[[\"," + std::string(600, '[') + "]"),
              "s.json: invalid JSON: arrays and objects nested more than 512 deep, at line 1, "
              "column 519 (byte 519)");
}

TEST(SceneLimits, MillionEmptyObjectsReachTheObjectCountRefusal) {
    // The duplicate-key check once rescanned the parent after every object: quadratic, so
    // this file (3 MB) took minutes. Now parsing is linear and the count check answers.
    std::string text = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "objects": [)";
    text.reserve(text.size() + 3 * (kMaxObjects + 1) + 2);
    for (size_t i = 0; i <= kMaxObjects; ++i) text += i ? ",{}" : "{}";
    text += "]}";
    try {
        (void)parse_scene(text, "s.json");
        FAIL() << "accepted";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "objects: holds 1000001 objects, more than the 1000000 allowed");
    }
}

TEST(SceneLimits, DuplicateKeyIsNamedByItsPath) {
    EXPECT_EQ(json_refusal(R"({"objects": [{"x": 1}, {"y": 2, "y": 3}]})"),
              "objects[1].y: key given twice in the same object");
}

TEST(SceneLimits, JsonWhoseValuesOutgrowTheMemoryBudgetIsRefused) {
    // Each number in an array costs 32 bytes of the budget: with 1 MiB, 32767 fit beside the
    // array itself, one more is refused (the default budget, kMaxJsonValueBytes, works alike).
    auto numbers = [](size_t n) {
        std::string text = "[";
        for (size_t i = 0; i < n; ++i) text += i ? ",0" : "0";
        return text + "]";
    };
    EXPECT_NO_THROW(parse_json_strict(numbers(32767), "s.json", uint64_t{1} << 20));
    try {
        (void)parse_json_strict(numbers(32768), "s.json", uint64_t{1} << 20);
        FAIL() << "accepted";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(),
                     "s.json: too large: its values would take more than 1 MiB of memory once "
                     "read (stopped after 32769 values)");
    }
}

TEST(SceneLimits, MeshTriangleCountSharesTheCountCheck) {
    // A mesh over 10 million triangles is a gigabyte of JSON; the reader refuses it with
    // check_count, whose wording this pins.
    try {
        check_count(kMaxMeshTriangles + 1, kMaxMeshTriangles, "objects[0].faces", "faces");
        FAIL() << "no refusal";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(),
                     "objects[0].faces: holds 10000001 faces, more than the 10000000 allowed");
    }
    EXPECT_NO_THROW(check_count(kMaxMeshTriangles, kMaxMeshTriangles, "objects[0].faces", "faces"));
}

}  // namespace
}  // namespace lenslab
