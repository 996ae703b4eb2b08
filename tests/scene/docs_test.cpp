// docs/scenes.md and the schema agree: every key the parser accepts is documented, every
// documented key is accepted, and the generated key reference is current.
// To refresh the reference after a schema change: SYSTOLE_UPDATE_DOCS=1 ./test_scene

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "scene/schema.h"
#include "scene_test_util.h"

namespace systole::scene {
namespace {

const std::filesystem::path kDocs = std::filesystem::path(SYSTOLE_SOURCE_DIR) / "docs" / "scenes.md";
constexpr const char* kBegin = "<!-- BEGIN KEY REFERENCE (generated from src/scene/schema.cpp) -->\n";
constexpr const char* kEnd = "<!-- END KEY REFERENCE -->";

std::string read_docs() {
  std::ifstream in(kDocs);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The first cell of every table row: | `organs[].body.mass` | ... (digits too: audio.heart.s1)
std::set<std::string> documented_keys(const std::string& docs) {
  std::set<std::string> keys;
  const std::regex row(R"(^\| `([a-z0-9_\[\].]+)` \|)", std::regex::multiline);  // s1, s2: keys with digits
  for (auto it = std::sregex_iterator(docs.begin(), docs.end(), row); it != std::sregex_iterator(); ++it)
    keys.insert((*it)[1]);
  return keys;
}

TEST(SceneDocs, EveryAcceptedKeyIsDocumentedAndEveryDocumentedKeyIsAccepted) {
  const std::string docs = read_docs();
  ASSERT_FALSE(docs.empty()) << "cannot read " << kDocs;
  const std::set<std::string> documented = documented_keys(docs);
  const std::vector<std::string> paths = key_paths();
  const std::set<std::string> accepted(paths.begin(), paths.end());
  for (const std::string& key : accepted) EXPECT_TRUE(documented.count(key)) << key << " is accepted but not in " << kDocs;
  for (const std::string& key : documented) EXPECT_TRUE(accepted.count(key)) << key << " is in " << kDocs << " but not accepted";
  EXPECT_GT(accepted.size(), 60u);  // the walk really covers the nested maps
}

TEST(SceneDocs, DocumentedKeysReallyParse) {
  // Spot-check the documentation paths against the parser itself, not only the table.
  const std::vector<std::string> paths = key_paths();
  EXPECT_TRUE(std::count(paths.begin(), paths.end(), "organs[].regions[].drive.rate"));
  EXPECT_TRUE(std::count(paths.begin(), paths.end(), "organs[].regions[].select.sphere.radius"));
  const auto f = testing::load_error(testing::kMinimalOrgans, {"organs.0.regions=[{name: lv, select: {sphere: {radius: 1 cm}}}]"});
  EXPECT_TRUE(f.message.empty()) << f.message;
}

TEST(SceneDocs, GeneratedReferenceIsCurrent) {
  std::string docs = read_docs();
  const std::size_t begin = docs.find(kBegin);
  const std::size_t end = docs.find(kEnd);
  ASSERT_NE(begin, std::string::npos) << kDocs << " lacks " << kBegin;
  ASSERT_NE(end, std::string::npos) << kDocs << " lacks " << kEnd;
  const std::size_t from = begin + std::string(kBegin).size();
  const std::string generated = "\n" + reference_markdown();
  if (std::getenv("SYSTOLE_UPDATE_DOCS")) {
    docs.replace(from, end - from, generated);
    std::ofstream(kDocs) << docs;
    GTEST_SKIP() << "rewrote the key reference in " << kDocs;
  }
  EXPECT_EQ(docs.substr(from, end - from), generated)
      << "the key reference in " << kDocs << " is stale; run SYSTOLE_UPDATE_DOCS=1 test_scene";
}

}  // namespace
}  // namespace systole::scene
