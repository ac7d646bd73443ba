// Replays every fuzz input kept in the repository through the same entry points the
// libFuzzer targets use (fuzz/fuzz_inputs.h), built with the project's compiler: the corpus
// (tests/fuzz/corpus/<target>) and every crash or hang the fuzzers ever found
// (tests/fuzz/regressions/<target>). Under the asan preset this is a sanitized replay too.
// A finding comes back as a crash, a sanitizer report, or an exception other than the
// documented SceneError / FormulaError / ObjError / CLI::ParseError, which fails the test and names
// the file.

#include <gtest/gtest.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_inputs.h"

namespace {

namespace fs = std::filesystem;

// The input files of one folder, in a fixed order; README.md explains the folder.
std::vector<fs::path> inputs_in(const std::string& folder) {
    std::vector<fs::path> files;
    const fs::path dir = fs::path(LENSLAB_TEST_DATA) / "fuzz" / folder;
    if (!fs::is_directory(dir)) return files;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.is_regular_file() && entry.path().filename() != "README.md")
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string contents(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Feeds every file of `folder` to `feed`; returns how many were replayed.
size_t replay(const std::string& folder, const std::function<void(const std::string&)>& feed) {
    const std::vector<fs::path> files = inputs_in(folder);
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        try {
            feed(contents(file));
        } catch (const std::exception& e) {
            ADD_FAILURE() << file << " threw an undocumented exception: " << e.what();
        }
    }
    return files.size();
}

void scene(const std::string& data) {
    lenslab::fuzz::read_scene_input(data, std::string(LENSLAB_SOURCE_DIR) + "/scenes");
}
void formula(const std::string& data) { lenslab::fuzz::parse_formula_input(data); }
void obj(const std::string& data) { lenslab::fuzz::read_obj_input(data); }
void argv(const std::string& data) { lenslab::fuzz::parse_argv_input(data); }

TEST(FuzzReplay, SceneCorpus) {
    // The seeds alone are over a hundred files (scenes, bad scenes, the format's examples).
    EXPECT_GE(replay("corpus/scene", scene), 100u);
}

TEST(FuzzReplay, SceneRegressions) { replay("regressions/scene", scene); }

TEST(FuzzReplay, FormulaCorpus) { EXPECT_GE(replay("corpus/formula", formula), 50u); }

TEST(FuzzReplay, FormulaRegressions) { replay("regressions/formula", formula); }

// The seeds: the OBJ files of the tests, good and bad, and the reader's forms.
TEST(FuzzReplay, ObjCorpus) { EXPECT_GE(replay("corpus/obj", obj), 12u); }

TEST(FuzzReplay, ObjRegressions) { replay("regressions/obj", obj); }

// The seeds: command lines of every command, good and bad, one argument a line.
TEST(FuzzReplay, ArgvCorpus) { EXPECT_GE(replay("corpus/argv", argv), 12u); }

TEST(FuzzReplay, ArgvRegressions) { replay("regressions/argv", argv); }

}  // namespace
