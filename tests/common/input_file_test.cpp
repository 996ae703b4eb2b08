// Why a path cannot be read as a file (common/input_file.h), for each kind of path that is
// not a readable regular file.

#include "common/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace systole {
namespace {

namespace fs = std::filesystem;

/// A folder of this test's own (ctest may run the tests of one program at once).
fs::path scratch() {
  const fs::path dir = fs::path(SYSTOLE_TEST_SCRATCH) / "input_file" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(InputFile, AReadableFileHasNoReason) {
  const fs::path dir = scratch();
  std::ofstream(dir / "heart.obj") << "v 0 0 0\n";
  EXPECT_EQ(unreadable_file_reason(dir / "heart.obj"), std::nullopt);
  // Through a symbolic link to it, too.
  fs::create_symlink(dir / "heart.obj", dir / "link.obj");
  EXPECT_EQ(unreadable_file_reason(dir / "link.obj"), std::nullopt);
}

TEST(InputFile, AMissingFileIsNotFound) {
  const fs::path dir = scratch();
  EXPECT_EQ(unreadable_file_reason(dir / "absent.obj"), "not found");
  // A path through a file as if it were a folder is missing too.
  std::ofstream(dir / "file") << "x";
  EXPECT_EQ(unreadable_file_reason(dir / "file" / "inside.obj"), "not found");
}

TEST(InputFile, ABrokenLinkNamesWhereItPoints) {
  const fs::path dir = scratch();
  fs::create_symlink("nowhere.obj", dir / "broken.obj");
  const auto reason = unreadable_file_reason(dir / "broken.obj");
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("broken symbolic link"), std::string::npos) << *reason;
  EXPECT_NE(reason->find("'nowhere.obj'"), std::string::npos) << *reason;
}

TEST(InputFile, ALinkLoopIsCalledOne) {
  const fs::path dir = scratch();
  fs::create_symlink("b", dir / "a");
  fs::create_symlink("a", dir / "b");
  const auto reason = unreadable_file_reason(dir / "a");
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("loop"), std::string::npos) << *reason;
}

TEST(InputFile, AFolderOrAPipeIsNotAFile) {
  const fs::path dir = scratch();
  const auto folder = unreadable_file_reason(dir);
  ASSERT_TRUE(folder);
  EXPECT_NE(folder->find("directory"), std::string::npos) << *folder;
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  const auto pipe = unreadable_file_reason(dir / "pipe");
  ASSERT_TRUE(pipe);
  EXPECT_NE(pipe->find("not a regular file"), std::string::npos) << *pipe;
}

TEST(InputFile, AFileWithoutReadPermissionIsNotReadable) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads every file";
  const fs::path dir = scratch();
  std::ofstream(dir / "secret.obj") << "v 0 0 0\n";
  fs::permissions(dir / "secret.obj", fs::perms::none);
  const auto reason = unreadable_file_reason(dir / "secret.obj");
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("not readable"), std::string::npos) << *reason;
}

}  // namespace
}  // namespace systole
