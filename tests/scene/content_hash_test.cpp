#include "scene/content_hash.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/error.h"
#include "support/run.h"

using namespace systole::test;  // support/run.h

namespace systole::scene {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

TEST(SceneHash, ChangesWithTheSceneFileAndWithEveryMeshItNames) {
  const fs::path dir = test::scratch("scene_hash");
  write(dir / "a.yaml", "name: a\n");
  write(dir / "m.obj", "v 0 0 0\n");
  scene::Scene s;
  s.path = (dir / "a.yaml").string();
  const auto bare = scene_content_hash(s);
  EXPECT_EQ(scene_content_hash(s), bare);  // A pure function of the bytes.

  s.organs.emplace_back();
  EXPECT_EQ(scene_content_hash(s), bare);  // A procedural organ reads no file.
  s.organs.back().mesh.file = (dir / "m.obj").string();
  const auto with_mesh = scene_content_hash(s);
  EXPECT_NE(with_mesh, bare);

  write(dir / "m.obj", "v 0 0 1\n");
  EXPECT_NE(scene_content_hash(s), with_mesh);
  write(dir / "a.yaml", "name: b\n");
  const auto renamed = scene_content_hash(s);
  write(dir / "m.obj", "v 0 0 0\n");
  EXPECT_NE(scene_content_hash(s), renamed);
}

TEST(SceneHash, AnUnreadableInputIsNoInput) {
  scene::Scene s;
  s.path = (test::scratch("scene_hash_missing") / "absent.yaml").string();
  try {
    scene_content_hash(s);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kNoInput);
    EXPECT_NE(std::string(e.what()).find("absent.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace systole::scene
