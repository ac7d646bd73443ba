// Files are written whole or not at all (util/atomic_file.h): the content appears under
// its name only once complete, a failure leaves the old file as it was, and no temporary
// file survives either way.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "image/image_io.h"
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

// Issue 15: the rules of util/output_path.h, as write_atomically follows them.

TEST_F(AtomicFile, AReadOnlyFileIsRefusedAndLeftAsItWas) {
    // chmod 444: not writable by anyone but root, and for root (whom access(W_OK) always
    // lets through) the missing write bits decide, so the rule holds for both.
    write_text_atomically(path("kept.csv"), "old");
    fs::permissions(path("kept.csv"),
                    fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    try {
        write_text_atomically(path("kept.csv"), "new");
        FAIL() << "no error";
    } catch (const FileWriteError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cannot write '" + path("kept.csv") + "': the file is read-only");
    }
    EXPECT_EQ(read(path("kept.csv")), "old");
    EXPECT_EQ(files(), 1u);
}

TEST_F(AtomicFile, AnExistingFileKeepsItsPermissionBitsANewOneGetsTheUmasks) {
    write_text_atomically(path("private.csv"), "old");
    chmod(path("private.csv").c_str(), 0600);
    write_text_atomically(path("private.csv"), "new");
    struct stat st {};
    ASSERT_EQ(stat(path("private.csv").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0600u);
    EXPECT_EQ(read(path("private.csv")), "new");

    const mode_t mask = umask(022);
    write_text_atomically(path("fresh.csv"), "text");
    umask(mask);
    ASSERT_EQ(stat(path("fresh.csv").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0644u);
}

TEST_F(AtomicFile, ASymbolicLinkIsWrittenThroughAndStaysALink) {
    fs::create_directories(path("real"));
    write_text_atomically(path("real/data.csv"), "old");
    fs::create_symlink("real/data.csv", path("link.csv"));  // relative, like most links
    fs::create_symlink("link.csv", path("link_to_link.csv"));
    write_text_atomically(path("link_to_link.csv"), "new");
    EXPECT_EQ(read(path("real/data.csv")), "new");
    EXPECT_TRUE(fs::is_symlink(path("link.csv")));
    EXPECT_TRUE(fs::is_symlink(path("link_to_link.csv")));
    // A dangling link: the file is made where it points.
    fs::create_symlink("real/made.png", path("made.png"));
    Film film(2, 2);
    write_image(film, path("made.png"));
    EXPECT_TRUE(fs::is_symlink(path("made.png")));
    EXPECT_EQ(read_png(path("real/made.png")).width, 2);
    EXPECT_EQ(std::distance(fs::directory_iterator(path("real")), fs::directory_iterator()), 2);
}

TEST_F(AtomicFile, AFullDeviceIsReportedAsNoSpaceNeverAsSuccess) {
    if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
    // Devices only through links in the test's folder: the old rename replaced its target,
    // and as root that was the device node itself.
    const std::string no_space = "no space left on device";
    fs::create_symlink("/dev/full", path("full.csv"));
    try {
        write_text_atomically(path("full.csv"), "text");
        FAIL() << "no error";
    } catch (const FileWriteError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write '" + path("full.csv") + "': " + no_space);
    }
    // The writer under every text file, on its own.
    try {
        write_whole_file("/dev/full", "text", "out.csv");
        FAIL() << "no error";
    } catch (const FileWriteError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write 'out.csv': " + no_space);
    }
    // An image through a link to it: the link is followed, and kept.
    fs::create_symlink("/dev/full", path("full.png"));
    Film film(4, 3);
    try {
        write_image(film, path("full.png"));
        FAIL() << "no error";
    } catch (const ImageError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write '" + path("full.png") + "': " + no_space);
    }
    EXPECT_TRUE(fs::is_symlink(path("full.png")));
    // A device that takes everything takes a file too.
    fs::create_symlink("/dev/null", path("null.csv"));
    write_text_atomically(path("null.csv"), "text");
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
    EXPECT_EQ(files(), 3u);  // the three links, and no temporary
}

TEST_F(AtomicFile, ANameOfTwoHundredAndFiftyCharactersCanBeWritten) {
    // NAME_MAX is 255: the old temporary name "<name>.tmp<pid><ext>" did not fit.
    const std::string name = std::string(246, 'n') + ".png";
    ASSERT_EQ(name.size(), 250u);
    EXPECT_LT(fs::path(temporary_path_for(path(name))).filename().string().size(), 60u);
    Film film(2, 2);
    write_image(film, path(name));
    write_text_atomically(path(std::string(246, 't') + ".csv"), "text");
    EXPECT_EQ(read_png(path(name)).height, 2);
    EXPECT_EQ(files(), 2u);
}

TEST_F(AtomicFile, AFolderIsNotReplaced) {
    fs::create_directories(path("empty_folder"));
    try {
        write_text_atomically(path("empty_folder"), "text");
        FAIL() << "no error";
    } catch (const FileWriteError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cannot write '" + path("empty_folder") + "': is a directory");
    }
    EXPECT_TRUE(fs::is_directory(path("empty_folder")));
}

}  // namespace
}  // namespace lenslab
