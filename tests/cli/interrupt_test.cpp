// A render that fails part-way never touches earlier work. SIGINT or SIGTERM mid-render
// removes the temporary output and exits with 128 + the signal (130, 143); SIGKILL cannot
// clean up, so the next run in that folder does; a full disk fails the run with an I/O
// error. In every case the earlier video and its manifest stay byte for byte as they were.
// And two renders to one output: exactly one writes it.

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <gtest/gtest.h>
#include <thread>

#include "support/background.h"
#include "support/run.h"
#include "support/small_disk.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

/// What a finished render leaves: the video and the manifest that vouches for it.
struct Earlier {
  fs::path video;
  std::string video_bytes, manifest_bytes;

  /// Renders a short clip to `video` the ordinary way.
  explicit Earlier(fs::path target) : video(std::move(target)) {
    const RunResult r = run(systole() + " render " + source("scenes/heart.yaml") +
                            " -D output.width=160 -D output.height=120 -D output.duration=0.2s -o " + quoted(video));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    video_bytes = read_file(video);
    manifest_bytes = read_file(video.string() + ".json");
    EXPECT_FALSE(video_bytes.empty());
    EXPECT_NE(manifest_bytes.find("\"video_checksum\""), std::string::npos);
  }
  void expect_untouched() const {
    EXPECT_TRUE(read_file(video) == video_bytes) << "the earlier video is byte-identical";
    EXPECT_EQ(read_file(video.string() + ".json"), manifest_bytes) << "its manifest is byte-identical";
  }
};

/// Temporaries and lock files of outputs in `dir` (what a run must not leave behind).
std::vector<std::string> leftovers(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".partial-") != std::string::npos || name.ends_with(".lock")) names.push_back(name);
  }
  return names;
}

/// The temporary AtomicOutput writes beside `target` (.<name>.partial-<pid>-<n><ext>), if any.
fs::path partial_of(const fs::path& target) {
  for (const auto& entry : fs::directory_iterator(target.parent_path())) {
    if (entry.path().filename().string().starts_with("." + target.filename().string() + ".partial-")) return entry.path();
  }
  return {};
}

/// The arguments of a long render of the heart to `video`.
std::vector<std::string> long_render_args(const fs::path& video, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"render", source("scenes/heart.yaml"), "-D", "output.width=160", "-D",
                                   "output.height=120", "-D", "output.duration=60 s", "-o", video.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

/// A long render of the heart to `video`, in the background.
struct LongRender : Background {
  explicit LongRender(const fs::path& video, const std::vector<std::string>& extra = {})
      : Background(long_render_args(video, extra), video.parent_path() / "stderr.txt") {}
  /// Waits until the encoder has written into the temporary file; false if the run ended first.
  bool wait_until_writing(const fs::path& video) {
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (!ended() && std::chrono::steady_clock::now() < deadline) {
      const fs::path partial = partial_of(video);
      std::error_code ec;
      if (!partial.empty() && fs::file_size(partial, ec) > 0 && !ec) return true;
      std::this_thread::sleep_for(10ms);
    }
    return false;
  }
};

void expect_clean_stop(int sig, int expected_code) {
  const auto dir = scratch("interrupt_" + std::to_string(sig));
  const Earlier earlier(dir / "clip.mp4");
  LongRender render(earlier.video);
  ASSERT_TRUE(render.wait_until_writing(earlier.video)) << "the render never wrote its temporary file:\n"
                                                        << render.stderr_text();
  EXPECT_EQ(render.finish(sig), expected_code) << render.stderr_text();
  EXPECT_NE(render.stderr_text().find("interrupted; no output was written"), std::string::npos) << render.stderr_text();
  earlier.expect_untouched();
  fs::remove(render.log);
  EXPECT_TRUE(leftovers(dir).empty()) << "no temporary or lock file is left: " << leftovers(dir).front();
}

TEST(Interrupt, SigintMidRenderRemovesTheTemporaryAndExits130) { expect_clean_stop(SIGINT, 130); }

TEST(Interrupt, SigtermMidRenderRemovesTheTemporaryAndExits143) { expect_clean_stop(SIGTERM, 143); }

TEST(Interrupt, SigkillLeavesFilesThatTheNextRunInTheFolderRemoves) {
  const auto dir = scratch("interrupt_kill");
  const Earlier earlier(dir / "clip.mp4");
  LongRender render(earlier.video);
  ASSERT_TRUE(render.wait_until_writing(earlier.video)) << render.stderr_text();
  EXPECT_EQ(render.finish(SIGKILL), 128 + SIGKILL);
  earlier.expect_untouched();
  fs::remove(render.log);
  EXPECT_EQ(leftovers(dir).size(), 2u) << "what a killed run leaves: its temporary and its lock";

  // The next run in that folder writes something else, and cleans up what the dead one left.
  const Earlier next(dir / "other.mp4");
  EXPECT_TRUE(leftovers(dir).empty()) << leftovers(dir).front();
  earlier.expect_untouched();
}

TEST(Interrupt, ASecondRenderToTheSameOutputIsRefusedWhileTheFirstWrites) {
  const auto dir = scratch("interrupt_concurrent");
  const Earlier earlier(dir / "clip.mp4");
  LongRender first(earlier.video, {"--force"});
  ASSERT_TRUE(first.wait_until_writing(earlier.video)) << first.stderr_text();
  const RunResult second = run(systole() + " render " + source("scenes/heart.yaml") +
                               " -D output.width=160 -D output.height=120 -D output.duration=0.2s --force -o " +
                               quoted(earlier.video));
  EXPECT_EQ(second.exit_code, 75) << second.output;
  EXPECT_NE(second.output.find("'" + earlier.video.string() + "' is being written by another run (pid " +
                               std::to_string(first.pid) + " on "),
            std::string::npos)
      << second.output;
  earlier.expect_untouched();
  EXPECT_EQ(first.finish(SIGTERM), 143) << "the first run was still writing";
  earlier.expect_untouched();
  fs::remove(first.log);
  EXPECT_TRUE(leftovers(dir).empty()) << leftovers(dir).front();
}

TEST(Interrupt, AFullDiskFailsTheRunAndLeavesTheEarlierVideoAndManifest) {
  const SmallDisk disk(scratch("interrupt_full_disk") / "disk", "1m");
  if (!disk.mounted) GTEST_SKIP() << kNoSmallDisk;
  const Earlier earlier(disk.dir / "clip.mp4");
  // Lossless frames fill the megabyte within a second of video.
  const RunResult r = run(systole() + " render " + source("scenes/heart.yaml") +
                          " -D output.width=320 -D output.height=240 -D output.duration=20s -D output.crf=0 --force -o " +
                          quoted(earlier.video));
  EXPECT_EQ(r.exit_code, 74) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  earlier.expect_untouched();
  EXPECT_TRUE(leftovers(disk.dir).empty()) << leftovers(disk.dir).front();
}

}  // namespace
}  // namespace systole::test
