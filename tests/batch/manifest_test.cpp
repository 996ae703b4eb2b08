#include "batch/manifest.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/run.h"

using namespace systole::test;  // support/run.h

namespace systole::batch {
namespace {

namespace fs = std::filesystem;

JobIdentity job() { return {"scenes/heart.yaml", 0x1234, {"output.fps=24"}, "", 0}; }

TEST(Manifest, EveryFieldButThePathTextChangesTheKey) {
  const auto key = job().key();
  EXPECT_EQ(job().key(), key);
  auto j = job();
  j.scene_path = "elsewhere/heart.yaml";
  EXPECT_EQ(j.key(), key);  // The hash decides, not the path as typed.
  j = job(), j.scene_hash = 0x1235;
  EXPECT_NE(j.key(), key);
  j = job(), j.overrides.push_back("output.width=64");
  EXPECT_NE(j.key(), key);
  j = job(), j.frames = "0..9";
  EXPECT_NE(j.key(), key);
  j = job(), j.bake_checksum = 7;
  EXPECT_NE(j.key(), key);
  // Overrides in another order are another job (the last one wins).
  auto a = job(), b = job();
  a.overrides = {"x=1", "x=2"}, b.overrides = {"x=2", "x=1"};
  EXPECT_NE(a.key(), b.key());
}

TEST(Manifest, UpToDateOnlyWithItsManifestItsKeyAndTheVideosBytes) {
  const fs::path dir = test::scratch("manifest");
  const fs::path video = dir / "clip.mp4";
  EXPECT_EQ(manifest_path(video), dir / "clip.mp4.json");
  EXPECT_FALSE(up_to_date(video, job()));  // No video.
  test::write_file(video, "frames");
  EXPECT_FALSE(up_to_date(video, job()));  // No manifest.
  write_manifest(video, job());
  EXPECT_TRUE(fs::exists(manifest_path(video)));
  EXPECT_TRUE(up_to_date(video, job()));
  auto other = job();
  other.frames = "3";
  EXPECT_FALSE(up_to_date(video, other));
  test::write_file(video, "frames replaced by hand");
  EXPECT_FALSE(up_to_date(video, job()));
  write_manifest(video, job());
  EXPECT_TRUE(up_to_date(video, job()));
  // A video of the same size but other bytes (a run of this job that died after its video
  // replaced the old one, before its manifest did) is not vouched for.
  test::write_file(video, "frames REPLACED by hand");
  EXPECT_FALSE(up_to_date(video, job()));
  EXPECT_NE(test::read_file(manifest_path(video)).find("\"video_checksum\": \""), std::string::npos);
}

}  // namespace
}  // namespace systole::batch
