// `lenslab sweep` end to end, through the binary: frames written once each, a second run
// resuming (skipping what is there), and --analyze's CSV against the lensmaker's equation.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "optics/glass.h"
#include "optics/glass_library.h"

namespace {

namespace fs = std::filesystem;

struct SweepRun {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// Runs `lenslab ARGS` from the source folder, so the scene paths are the short ones.
SweepRun run_sweep_command(const std::string& args) {
    const std::string command = std::string("cd '") + LENSLAB_SOURCE_DIR + "' && '" +
                                LENSLAB_BINARY + "' " + args + " 2>&1";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    SweepRun run;
    std::array<char, 4096> buffer{};
    while (pipe && fgets(buffer.data(), buffer.size(), pipe.get())) run.output += buffer.data();
    const int status = pclose(pipe.release());
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

// A fresh folder for one test's sweep.
fs::path sweep_test_folder(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("lenslab_sweep_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    return dir;
}

std::vector<std::vector<std::string>> read_csv_rows(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::stringstream cellstream(line);
        for (std::string cell; std::getline(cellstream, cell, ',');) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

const std::string kTinyRender =
    " --width 24 --height 16 --spp 1 --photons 2000 --caustic-photons 2000 --threads 1 -q";

TEST(SweepCommand, RendersEachFrameOnceAndResumes) {
    const fs::path dir = sweep_test_folder("render");
    const std::string sweep =
        "sweep scenes/lens_caustic.json --set /objects/1/center/1=1.5:4.5:3 -o " + dir.string() +
        kTinyRender;
    const SweepRun first = run_sweep_command(sweep);
    ASSERT_EQ(first.exit_code, 0) << first.output;
    for (const char* frame : {"00000.png", "00001.png", "00002.png"})
        EXPECT_TRUE(fs::is_regular_file(dir / "frames" / frame)) << frame;
    EXPECT_FALSE(fs::exists(dir / "frames" / "00003.png"));
    EXPECT_TRUE(fs::is_regular_file(dir / "sweep.json"));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "frames"), fs::directory_iterator{}), 3)
        << "no temporary file left behind";

    // Everything there: nothing is rendered again.
    const SweepRun again = run_sweep_command(sweep);
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find("skipped 3 of 3 frames already in"), std::string::npos)
        << again.output;
    EXPECT_EQ(again.output.find(".png ("), std::string::npos) << again.output;

    // A frame missing (an interrupted sweep): only it is rendered.
    fs::remove(dir / "frames" / "00001.png");
    const SweepRun resumed = run_sweep_command(sweep);
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("skipped 2 of 3 frames"), std::string::npos) << resumed.output;
    EXPECT_NE(resumed.output.find("00001.png ("), std::string::npos) << resumed.output;
    EXPECT_EQ(resumed.output.find("00000.png ("), std::string::npos) << resumed.output;
    EXPECT_TRUE(fs::is_regular_file(dir / "frames" / "00001.png"));

    // --overwrite renders them all again.
    const SweepRun overwrite = run_sweep_command(sweep + " --overwrite");
    ASSERT_EQ(overwrite.exit_code, 0) << overwrite.output;
    EXPECT_EQ(overwrite.output.find("skipped"), std::string::npos) << overwrite.output;
    fs::remove_all(dir);
}

TEST(SweepCommand, ProgressNamesEachFrameAndItsValue) {
    const fs::path dir = sweep_test_folder("progress");
    const SweepRun run = run_sweep_command(
        "sweep scenes/lens_caustic.json --set /objects/1/center/1=2:3:2 -o " + dir.string() +
        " --width 8 --height 8 --spp 1 --photons 500 --caustic-photons 500 --threads 1");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("frame 1/2 (/objects/1/center/1 = 2)"), std::string::npos);
    EXPECT_NE(run.output.find("frame 2/2 (/objects/1/center/1 = 3)"), std::string::npos);
    fs::remove_all(dir);
}

// A plano-convex lens's focal length is R / (n - 1) exactly, thick or thin (its flat side has
// no power): the EFL column must follow the swept radius of curvature.
TEST(SweepCommand, AnalyzeCsvFollowsTheLensmakersEquation) {
    const fs::path dir = sweep_test_folder("analyze");
    const SweepRun run = run_sweep_command(
        "sweep tests/analysis/data/lens_only.json --set /objects/0/front/radius=20:60:5 "
        "--analyze -o " +
        dir.string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const auto rows = read_csv_rows(dir / "sweep.csv");
    ASSERT_EQ(rows.size(), 6u);
    const std::vector<std::string>& header = rows[0];
    ASSERT_GE(header.size(), 4u);
    EXPECT_EQ(header[0], "frame");
    EXPECT_EQ(header[1], "/objects/0/front/radius");
    const auto column = [&header](const std::string& name) {
        return std::find(header.begin(), header.end(), name) - header.begin();
    };
    const auto efl = column("efl");
    ASSERT_LT(efl, static_cast<long>(header.size()));
    ASSERT_LT(column("bfl"), static_cast<long>(header.size()));
    ASSERT_LT(column("rms_spot_best"), static_cast<long>(header.size()));
    const double n = lenslab::lookup_glass("N-BK7").glass->model->n(lenslab::kLineD);
    for (int frame = 0; frame < 5; ++frame) {
        const std::vector<std::string>& row = rows[frame + 1];
        ASSERT_EQ(row.size(), header.size());
        EXPECT_EQ(std::stoi(row[0]), frame);
        const double radius = std::stod(row[1]);
        EXPECT_DOUBLE_EQ(radius, 20.0 + 10.0 * frame);
        EXPECT_NEAR(std::stod(row[efl]), radius / (n - 1.0), 1e-9 * radius) << "frame " << frame;
        EXPECT_TRUE(
            fs::is_regular_file(dir / "frames" / ("0000" + std::to_string(frame) + ".json")));
    }
    EXPECT_TRUE(fs::is_regular_file(dir / "sweep.json"));
    fs::remove_all(dir);
}

// analyze's options reach every frame: at the F line the EFL is R / (n_F - 1).
TEST(SweepCommand, AnalyzeTakesTheBenchOptions) {
    const fs::path dir = sweep_test_folder("analyze_options");
    const SweepRun run = run_sweep_command(
        "sweep tests/analysis/data/lens_only.json --set /objects/0/front/radius=30:40:2 "
        "--analyze --wavelength 486.1327 --spots --fields 0,2 -q -o " +
        dir.string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const auto rows = read_csv_rows(dir / "sweep.csv");
    ASSERT_EQ(rows.size(), 3u);
    const auto& header = rows[0];
    const auto efl = std::find(header.begin(), header.end(), "efl") - header.begin();
    const auto wavelength =
        std::find(header.begin(), header.end(), "wavelength_nm") - header.begin();
    ASSERT_LT(efl, static_cast<long>(header.size()));
    ASSERT_LT(wavelength, static_cast<long>(header.size()));
    const double n_f = lenslab::lookup_glass("N-BK7").glass->model->n(lenslab::kLineF);
    for (int frame = 0; frame < 2; ++frame) {
        const auto& row = rows[frame + 1];
        EXPECT_DOUBLE_EQ(std::stod(row[wavelength]), 486.1327);
        EXPECT_NEAR(std::stod(row[efl]), std::stod(row[1]) / (n_f - 1.0), 1e-9 * 40);
    }
    std::ifstream frame(dir / "frames" / "00001.json");
    std::stringstream text;
    text << frame.rdbuf();
    EXPECT_NE(text.str().find("\"spots\""), std::string::npos) << "--spots reaches the frame";
    fs::remove_all(dir);
}

TEST(SweepCommand, AnimationAssemblesTheFrames) {
    if (access("/usr/bin/ffmpeg", X_OK) != 0) GTEST_SKIP() << "no /usr/bin/ffmpeg";
    const fs::path dir = sweep_test_folder("animation");
    const SweepRun run =
        run_sweep_command("sweep scenes/lens_caustic.json --set /objects/1/center/1=1.5:4.5:3 -o " +
                          dir.string() + kTinyRender + " --animation " +
                          (dir / "sweep.gif").string() + " --fps 5 --ffmpeg /usr/bin/ffmpeg");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    std::ifstream gif(dir / "sweep.gif", std::ios::binary);
    std::string magic(6, '\0');
    gif.read(magic.data(), 6);
    EXPECT_EQ(magic, "GIF89a");
    fs::remove_all(dir);
}

}  // namespace
