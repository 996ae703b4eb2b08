// The web page's vendored scripts, embedded at build time (export/viewer_assets.h): every
// script of third_party/three/ is there, byte for byte, though the build cuts each into
// pieces, and asking for one the build did not embed is an internal error.

#include "export/viewer_assets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "common/error.h"

namespace systole::exporter {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ViewerAssets, EveryVendoredScriptIsEmbeddedByteForByte) {
  const fs::path dir = fs::path(SYSTOLE_SOURCE_DIR) / "third_party" / "three";
  std::set<std::string> on_disk, embedded;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".js") on_disk.insert(entry.path().filename().string());
  }
  ASSERT_FALSE(on_disk.empty());
  for (const EmbeddedScript& s : embedded_scripts()) {
    embedded.insert(s.name);
    ASSERT_TRUE(on_disk.count(s.name)) << s.name;
    const std::string file = read(dir / s.name);
    EXPECT_EQ(s.text.size(), file.size()) << s.name;
    EXPECT_TRUE(s.text == file) << s.name << " differs from its file";
  }
  EXPECT_EQ(embedded, on_disk);
  // three.js itself is far longer than one piece of the embedding (60,000 characters).
  EXPECT_GT(embedded_script("three.module.min.js").size(), 120000u);
}

TEST(ViewerAssets, AScriptIsFoundByName) {
  for (const EmbeddedScript& s : embedded_scripts()) EXPECT_EQ(&embedded_script(s.name), &s.text);
}

TEST(ViewerAssets, AScriptTheBuildDidNotEmbedIsAnInternalError) {
  try {
    embedded_script("jquery.js");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kInternal);
  }
}

}  // namespace
}  // namespace systole::exporter
