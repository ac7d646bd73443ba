// Files are written whole or not at all (util/atomic_file.h): the content appears under
// its name only once complete, a failure leaves the old file as it was, and no temporary
// file survives either way.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "render/image_io.h"
#include "util/atomic_file.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("lenslab_atomic_" + std::to_string(getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string path(const std::string& name) const { return (m_dir / name).string(); }
    size_t files() const {
        return static_cast<size_t>(
            std::distance(fs::directory_iterator(m_dir), fs::directory_iterator()));
    }
    static std::string read(const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

    fs::path m_dir;
};

TEST_F(AtomicFile, TextIsWrittenAndNoTemporaryRemains) {
    write_text_atomically(path("a.csv"), "x,y\n1,2\n");
    EXPECT_EQ(read(path("a.csv")), "x,y\n1,2\n");
    write_text_atomically(path("a.csv"), "replaced\n");
    EXPECT_EQ(read(path("a.csv")), "replaced\n");
    EXPECT_EQ(files(), 1u);
}

TEST_F(AtomicFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
    write_text_atomically(path("scene.json"), "old");
    EXPECT_THROW(write_atomically(path("scene.json"),
                                  [](const std::string& tmp) {
                                      std::ofstream(tmp) << "half of the new";
                                      throw std::runtime_error("interrupted");
                                  }),
                 std::runtime_error);
    EXPECT_EQ(read(path("scene.json")), "old");
    EXPECT_EQ(files(), 1u);
}

TEST_F(AtomicFile, ARenameOntoAFolderFailsCleanly) {
    fs::create_directories(path("taken"));
    fs::create_directories(path("taken/inside"));  // a non-empty folder cannot be replaced
    EXPECT_THROW(write_text_atomically(path("taken"), "text"), FileWriteError);
    EXPECT_EQ(files(), 1u);
}

TEST_F(AtomicFile, ImagesAreWrittenAtomically) {
    Film film(4, 3);
    film.set(1, 1, {0.5, 0.25, 1});
    write_image(film, path("out.png"));
    write_image(film, path("out.exr"));
    EXPECT_EQ(files(), 2u);
    EXPECT_EQ(read_png(path("out.png")).width, 4);
    // A folder that does not exist: an ImageError naming the file, and nothing written.
    try {
        write_image(film, path("missing/out.png"));
        FAIL() << "no error";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("missing/out.png"), std::string::npos) << e.what();
    }
    EXPECT_EQ(files(), 2u);
}

}  // namespace
}  // namespace lenslab
