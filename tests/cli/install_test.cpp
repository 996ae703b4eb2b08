// `cmake --install` (cmake/Install.cmake) gives a tree that works without the source tree:
// the program, its man page and completions, Debian's copyright file, and the example scenes
// with the meshes they name, which still resolve from their installed folder.

#include <gtest/gtest.h>

#include <set>

#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

/// Installs the build into a fresh prefix of this test's own (ctest runs tests in parallel).
fs::path installed_prefix() {
  const fs::path p = scratch(std::string("install_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  const auto r = run(std::string(SYSTOLE_CMAKE_COMMAND) + " --install " + SYSTOLE_BUILD_DIR + " --prefix " + p.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return p;
}

std::set<std::string> yaml_files_under(const fs::path& dir) {
  std::set<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() == ".yaml") files.insert(fs::relative(entry.path(), dir).string());
  }
  return files;
}

TEST(Install, PutsEveryFileWhereDebianLooksForIt) {
  const fs::path prefix = installed_prefix();
  for (const char* file : {"bin/systole", "share/man/man1/systole.1.gz", "share/bash-completion/completions/systole",
                           "share/zsh/vendor-completions/_systole", "share/doc/systole/copyright",
                           "share/doc/systole/changelog.Debian.gz", "share/doc/systole/README.md",
                           "share/doc/systole/docs/scenes.md", "share/systole/scenes/meshes/stomach.obj",
                           "share/systole/scenes/meshes/heart-parts.glb"}) {
    EXPECT_TRUE(fs::is_regular_file(prefix / file)) << "not installed: " << file;
  }
  // Every scene of the source tree, and nothing else, in the same folders.
  EXPECT_EQ(yaml_files_under(prefix / "share/systole/scenes"), yaml_files_under(source("scenes")));
}

TEST(Install, CopyrightIsLicenceInDebiansFormat) {
  const std::string copyright = read_file(installed_prefix() / "share/doc/systole/copyright");
  EXPECT_EQ(copyright.rfind("Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n", 0), 0u)
      << copyright;
  EXPECT_NE(copyright.find("\nFiles: *\nCopyright: 2026 The Systole developers\nLicense: Expat\n"), std::string::npos)
      << copyright;
  // The licence's text, indented one space, with its blank lines as " .".
  EXPECT_NE(copyright.find("\n Permission is hereby granted, free of charge,"), std::string::npos) << copyright;
  EXPECT_NE(copyright.find("\n .\n THE SOFTWARE IS PROVIDED \"AS IS\""), std::string::npos) << copyright;
}

TEST(Install, InstalledProgramRunsAnInstalledSceneWithItsMeshFromAnEmptyFolder) {
  const fs::path prefix = installed_prefix();
  const fs::path empty = prefix / "empty_working_folder";
  fs::create_directories(empty);
  // own-mesh.yaml names meshes/stomach.obj relative to its own folder.
  const auto r = run("cd " + empty.string() + " && MESA_SHADER_CACHE_DISABLE=true " + (prefix / "bin/systole").string() +
                     " validate " + (prefix / "share/systole/scenes/own-mesh.yaml").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ok"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(empty)) << "validate wrote into the working folder";
}

}  // namespace
}  // namespace systole::test
