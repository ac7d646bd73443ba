// What `lenslab detect` writes for a detector: a CSV whose header states the units and
// whose cells hold the irradiance, an EXR, and the false-colour PNG; file names made safe.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/detectors/detector_files.h"
#include "analysis/detectors/detector_image.h"
#include "image/image_io.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

Scene beam_on_screen_scene() {
    // A 1 W beam of radius 0.5 on a 2 x 1 screen (unit mm): 1 / (pi 0.25) W/mm^2 inside.
    return parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [{"name": "screen: a/b", "type": "rectangle", "center": [0, 0, 2], "normal": [0, 0, -1],
                     "size": [2, 1], "material": {"color": 0.5}, "detector": {"resolution": [8, 4], "unit": "mm"}},
                    {"name": "screen: a/b", "type": "triangle", "vertices": [[5, 0, 2], [6, 0, 2], [5, 1, 2]],
                     "material": {"color": 0.5}, "detector": true}],
        "lights": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 0.5, "power": 1}]})");
}

DetectionResult beam_on_screen() {
    return measure_detectors(beam_on_screen_scene(), {.photons_per_light = 20000});
}

TEST(DetectorFiles, StemsAreSafeAndUnique) {
    const DetectionResult r = beam_on_screen();
    const auto stems = detector_file_stems(r);
    ASSERT_EQ(stems.size(), 2u);
    EXPECT_EQ(stems[0], "screen__a_b");
    EXPECT_EQ(stems[1], "screen__a_b_1");
    // Known from the scene alone, so `lenslab detect` checks its files before measuring.
    EXPECT_EQ(detector_file_stems(beam_on_screen_scene()), stems);
}

TEST(DetectorFiles, CsvStatesUnitsAndHoldsEveryCell) {
    const DetectionResult r = beam_on_screen();
    const DetectorMeasurement& m = r.detectors[0];
    DetectionSettings s;
    s.photons_per_light = 20000;
    std::istringstream csv(detector_csv(m, s));
    std::string line, header;
    int comments = 0, rows = 0;
    double sum = 0;
    while (std::getline(csv, line)) {
        if (line.rfind("#", 0) == 0) {
            ++comments;
            continue;
        }
        if (header.empty()) {
            header = line;
            continue;
        }
        ++rows;
        double u, v, area, e;
        char comma;
        std::istringstream row(line);
        row >> u >> comma >> v >> comma >> area >> comma >> e;
        sum += e * area;  // irradiance x area = power
    }
    EXPECT_EQ(header, "u,v,area,E_total,E_360_490nm,E_490_585nm,E_585_830nm");
    EXPECT_EQ(rows, 32);
    EXPECT_GE(comments, 4);
    EXPECT_NE(detector_csv(m, s).find("irradiance E in W/mm^2"), std::string::npos);
    EXPECT_NEAR(sum, m.total_power, 1e-9);
    EXPECT_NEAR(m.total_power, 1.0, 1e-9);
}

TEST(DetectorFiles, WritesCsvExrAndPng) {
    const DetectionResult r = beam_on_screen();
    const fs::path dir = fs::temp_directory_path() / "lenslab_test_detector_files";
    fs::create_directories(dir);
    DetectionSettings s;
    write_detector_files(r.detectors[0], s, dir.string(), "screen");
    for (const char* ext : {".csv", ".exr", ".png"})
        EXPECT_TRUE(fs::is_regular_file(dir / ("screen" + std::string(ext)))) << ext;
    std::ifstream exr(dir / "screen.exr", std::ios::binary);
    unsigned char magic[4] = {};
    exr.read(reinterpret_cast<char*>(magic), 4);
    EXPECT_EQ(magic[0], 0x76);  // OpenEXR magic number 20000630
    EXPECT_EQ(magic[1], 0x2f);
    const Image8 png = read_png((dir / "screen.png").string());
    const Image8 drawn = detector_image(r.detectors[0]);
    EXPECT_EQ(png.width, drawn.width);
    EXPECT_EQ(png.rgb, drawn.rgb);
    for (const auto& e : fs::directory_iterator(dir)) {
        EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
    }
    fs::remove_all(dir);
}

TEST(DetectorFiles, PictureShowsTheBeamWhereItLands) {
    // The map's middle is bright (the beam), its corners dark: the 2 x 1 screen is drawn
    // 512 x 256 from (16, 46).
    const DetectionResult r = beam_on_screen();
    const Image8 img = detector_image(r.detectors[0]);
    auto luma = [&](int x, int y) {
        const unsigned char* p = &img.rgb[(static_cast<size_t>(y) * img.width + x) * 3];
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    };
    EXPECT_GT(luma(16 + 256 + 40, 46 + 128 - 40), 150);
    EXPECT_LT(luma(16 + 10, 46 + 10), 30);
}

}  // namespace
}  // namespace lenslab
