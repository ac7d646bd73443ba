// Where an output may go is checked before any work (util/output_path.h): one message that
// names the path and the reason.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "util/output_path.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

class OutputPath : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("lenslab_output_path_" + std::to_string(getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string path(const std::string& name) const { return (m_dir / name).string(); }
    static std::string message_of_file_check(const std::string& p) {
        try {
            check_output_file(p);
        } catch (const FileWriteError& e) {
            return e.what();
        }
        return "";
    }
    static std::string message_of_folder_check(const std::string& p) {
        try {
            check_output_directory(p);
        } catch (const FileWriteError& e) {
            return e.what();
        }
        return "";
    }

    fs::path m_dir;
};

TEST_F(OutputPath, AFileMayBeNewOrAWritableFileOrADevice) {
    EXPECT_EQ(message_of_file_check(path("new.png")), "");
    std::ofstream(path("old.png")) << "old";
    const OutputTarget old = check_output_file(path("old.png"));
    EXPECT_EQ(old.kind, OutputTarget::Kind::RegularFile);
    EXPECT_EQ(message_of_file_check("/dev/null"), "");
    EXPECT_EQ(check_output_file("/dev/null").kind, OutputTarget::Kind::Stream);
}

TEST_F(OutputPath, AFileIsRefusedWithThePathAndTheReason) {
    fs::create_directories(path("folder"));
    EXPECT_EQ(message_of_file_check(path("folder")),
              "cannot write '" + path("folder") + "': is a directory");
    EXPECT_EQ(message_of_file_check(path("missing/out.png")),
              "cannot write '" + path("missing/out.png") + "': folder '" + path("missing") +
                  "' does not exist");
    std::ofstream(path("plain")) << "x";
    EXPECT_EQ(message_of_file_check(path("plain/out.png")),
              "cannot write '" + path("plain/out.png") + "': not a directory");
    fs::permissions(path("plain"), fs::perms::owner_read);
    EXPECT_EQ(message_of_file_check(path("plain")),
              "cannot write '" + path("plain") + "': the file is read-only");
    EXPECT_EQ(message_of_file_check(""), "cannot write '': no file name");
}

TEST_F(OutputPath, ALinkIsFollowedToTheFileItNames) {
    fs::create_directories(path("real"));
    fs::create_symlink("real/out.png", path("link.png"));  // dangling: the file is made there
    EXPECT_EQ(check_output_file(path("link.png")).path, path("real/out.png"));
    fs::create_symlink("nowhere/out.png", path("bad_link.png"));
    EXPECT_EQ(message_of_file_check(path("bad_link.png")), "cannot write '" + path("bad_link.png") +
                                                               "': folder '" + path("nowhere") +
                                                               "' does not exist");
    fs::create_symlink("loop_b", path("loop_a"));
    fs::create_symlink("loop_a", path("loop_b"));
    EXPECT_EQ(message_of_file_check(path("loop_a")),
              "cannot write '" + path("loop_a") + "': too many levels of symbolic links");
}

TEST_F(OutputPath, AFolderMustBeOneOrBeCreatable) {
    EXPECT_EQ(message_of_folder_check(path("")), "");
    EXPECT_EQ(message_of_folder_check(path("new/deeper")), "");
    std::ofstream(path("file")) << "x";
    EXPECT_EQ(message_of_folder_check(path("file")),
              "cannot write into folder '" + path("file") + "': is not a directory");
    EXPECT_EQ(message_of_folder_check(path("file/sub")),
              "cannot write into folder '" + path("file/sub") + "': not a directory");
    EXPECT_EQ(message_of_folder_check(""), "cannot write into folder '': no folder name");
    create_output_directory(path("made/here"));
    EXPECT_TRUE(fs::is_directory(path("made/here")));
    EXPECT_TRUE(fs::is_regular_file(path("file")));
}

}  // namespace
}  // namespace lenslab
