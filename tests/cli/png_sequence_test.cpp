// ctest-labels: slow-under-sanitizers
// An interrupted `--png DIR` run never leaves a mixed sequence (issue 38): after a full
// render, a second render in another colour stopped at any moment - SIGINT, SIGTERM,
// SIGKILL, a full disk - leaves the earlier frames and every other file in DIR byte for
// byte, and says truly that nothing was written. The next run in DIR removes what a killed
// run left, and finishes the final renames of a run killed during them (common/
// folder_update.h; that step is hit deterministically by a forked writer killed mid-commit).
// A --frames selection still writes only its own frames.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <optional>
#include <thread>

#include "common/folder_update.h"
#include "encode/png.h"
#include "support/background.h"
#include "support/run.h"
#include "support/small_disk.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr const char* kBlue = "organs.0.material.color=\"#3050c0\"";

/// A render of the heart at 160x120 into `dir` as PNG frames, with `extra` arguments.
std::vector<std::string> png_render(const fs::path& dir, const std::string& duration,
                                    const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"render", source("scenes/heart.yaml"), "-D", "output.width=160", "-D",
                                   "output.height=120", "-D", "output.duration=" + duration, "--no-video", "--png",
                                   dir.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

RunResult run_args(const std::vector<std::string>& args) {
  std::string command = systole();
  for (const std::string& a : args) command += " '" + a + "'";
  return run(command);
}

/// Every file under `dir` with its bytes, by relative path ("sub/" for a folder).
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(e.path(), dir).string();
    files[e.is_directory() ? name + "/" : name] = e.is_directory() ? "" : read_file(e.path());
  }
  return files;
}

/// The names in `a` and `b` whose bytes differ, or that only one has.
std::string differences(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b) {
  std::string names;
  for (const auto& [name, bytes] : a) {
    if (!b.contains(name) || b.at(name) != bytes) names += " " + name;
  }
  for (const auto& [name, bytes] : b) {
    if (!a.contains(name)) names += " +" + name;
  }
  return names;
}

/// What is beside `dir` in its parent: a run's staging folders, journal and lock.
std::vector<std::string> beside(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir.parent_path())) {
    if (e.path().filename() != dir.filename()) names.push_back(e.path().filename().string());
  }
  return names;
}

/// Frames a run has written so far into its staging folders beside `dir`.
int staged_frames(const fs::path& dir) {
  int frames = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir.parent_path(), ec)) {
    if (!e.path().filename().string().starts_with("." + dir.filename().string() + ".staging-")) continue;
    for (const auto& f : fs::directory_iterator(e.path(), ec)) frames += f.path().extension() == ".png" ? 1 : 0;
  }
  return frames;
}

/// A full render (6 frames) in DIR, and a note and a subfolder of the user's beside them.
struct EarlierSequence {
  fs::path dir;
  std::map<std::string, std::string> files;

  explicit EarlierSequence(fs::path folder) : dir(std::move(folder)) {
    const RunResult r = run_args(png_render(dir, "0.2 s"));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("wrote 6 PNG frames to " + dir.string()), std::string::npos) << r.output;
    write_file(dir / "notes.txt", "the user's own file");
    fs::create_directory(dir / "sub");
    write_file(dir / "sub" / "keep.txt", "and a folder of theirs");
    files = snapshot(dir);
    EXPECT_EQ(files.size(), 9u);
  }
  void expect_untouched(const std::string& when) const {
    const auto now = snapshot(dir);
    EXPECT_TRUE(now == files) << when << ": changed:" << differences(files, now);
  }
};

/// A 60-s render in blue (1800 frames, named as the earlier ones) into `dir`, started in the
/// background and waited for until `frames` frames are staged. Returns false if it ended first.
bool start_and_wait(std::optional<Background>& render, const fs::path& dir, const fs::path& log, int frames) {
  render.emplace(png_render(dir, "60 s", {"-D", kBlue}), log);
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (!render->ended() && std::chrono::steady_clock::now() < deadline) {
    if (staged_frames(dir) >= frames) return true;
    std::this_thread::sleep_for(5ms);
  }
  return false;
}

TEST(PngSequence, SigintOrSigtermAtAnyMomentLeavesTheEarlierSequenceAndSaysSo) {
  const fs::path root = scratch("png_interrupt");
  const EarlierSequence earlier(root / "out" / "frames");
  for (const int sig : {SIGINT, SIGTERM}) {
    for (const int moment : {1, 60}) {
      const std::string when = std::string(sig == SIGINT ? "SIGINT" : "SIGTERM") + " after " + std::to_string(moment) +
                               " frames";
      std::optional<Background> render;
      ASSERT_TRUE(start_and_wait(render, earlier.dir, root / "stderr.txt", moment)) << when << ": "
                                                                                     << render->stderr_text();
      EXPECT_EQ(render->finish(sig), 128 + sig) << when;
      EXPECT_NE(render->stderr_text().find("interrupted; no output was written"), std::string::npos)
          << when << ": " << render->stderr_text();
      earlier.expect_untouched(when);
      EXPECT_TRUE(beside(earlier.dir).empty()) << when << ": left " << beside(earlier.dir).front();
    }
  }
}

TEST(PngSequence, SigkillLeavesTheEarlierSequenceAndTheNextRunRemovesWhatItLeft) {
  const fs::path root = scratch("png_kill");
  const EarlierSequence earlier(root / "out" / "frames");
  for (const int moment : {1, 60}) {
    const std::string when = "SIGKILL after " + std::to_string(moment) + " frames";
    {
      std::optional<Background> render;
      ASSERT_TRUE(start_and_wait(render, earlier.dir, root / "stderr.txt", moment)) << when << ": "
                                                                                     << render->stderr_text();
      EXPECT_EQ(render->finish(SIGKILL), 128 + SIGKILL) << when;
    }
    earlier.expect_untouched(when);
    EXPECT_EQ(beside(earlier.dir).size(), 2u) << when << ": what SIGKILL leaves, its staging folder and lock";
  }
  // The next run in the folder: the earlier render again, which gives the same bytes.
  const RunResult next = run_args(png_render(earlier.dir, "0.2 s"));
  EXPECT_EQ(next.exit_code, 0) << next.output;
  earlier.expect_untouched("after the next run");
  EXPECT_TRUE(beside(earlier.dir).empty()) << "the next run removed them: " << beside(earlier.dir).front();
}

TEST(PngSequence, AFullDiskLeavesTheEarlierSequenceAndSaysWhy) {
  const SmallDisk disk(scratch("png_full_disk") / "disk", "1m");
  if (!disk.mounted) GTEST_SKIP() << kNoSmallDisk;
  const EarlierSequence earlier(disk.dir / "frames");
  const RunResult r = run_args(png_render(earlier.dir, "60 s", {"-D", kBlue}));
  EXPECT_EQ(r.exit_code, 74) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("cannot write '" + (earlier.dir / "frame_").string()), std::string::npos)
      << "names the frame in the folder asked for:\n" << r.output;
  EXPECT_EQ(r.output.find("staging"), std::string::npos) << r.output;
  earlier.expect_untouched("after the full disk");
  EXPECT_TRUE(beside(earlier.dir).empty()) << beside(earlier.dir).front();
}

TEST(PngSequence, AFinalStepKilledPartWayIsFinishedByTheNextRun) {
  const fs::path root = scratch("png_killed_swap");
  const EarlierSequence earlier(root / "out" / "frames");
  const fs::path blue = root / "blue";
  ASSERT_EQ(run_args(png_render(blue, "0.2 s", {"-D", kBlue})).exit_code, 0);
  // A run in blue killed during its final renames: a forked writer, killed after 3 of 6.
  const pid_t pid = ::fork();
  if (pid == 0) {
    FolderUpdate update(earlier.dir);
    for (int f = 0; f < 6; ++f) fs::copy_file(blue / encode::frame_file_name(f, 6), update.staged_path(encode::frame_file_name(f, 6)));
    update.commit([](int moved) {
      if (moved == 3) ::raise(SIGKILL);
    });
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
  ASSERT_TRUE(fs::exists(journal_path_of(earlier.dir))) << "killed after its journal";
  // The next run in the folder (any: here one frame in blue) finishes it first.
  const RunResult next = run_args(png_render(earlier.dir, "0.2 s", {"-D", kBlue, "--frames", "5"}));
  EXPECT_EQ(next.exit_code, 0) << next.output;
  auto expected = earlier.files;
  for (int f = 0; f < 6; ++f) expected[encode::frame_file_name(f, 6)] = read_file(blue / encode::frame_file_name(f, 6));
  const auto now = snapshot(earlier.dir);
  EXPECT_TRUE(now == expected) << "the whole blue sequence and the user's files; differ:" << differences(expected, now);
  EXPECT_TRUE(beside(earlier.dir).empty()) << beside(earlier.dir).front();
}

TEST(PngSequence, AFrameSelectionWritesOnlyItsFrames) {
  const fs::path root = scratch("png_selection");
  const EarlierSequence earlier(root / "out" / "frames");
  const RunResult r = run_args(png_render(earlier.dir, "0.2 s", {"-D", kBlue, "--frames", "1,3"}));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("wrote 2 PNG frames to " + earlier.dir.string()), std::string::npos) << r.output;
  const auto now = snapshot(earlier.dir);
  EXPECT_EQ(differences(earlier.files, now), " frame_00001.png frame_00003.png") << "the rest stays byte for byte";
  EXPECT_TRUE(beside(earlier.dir).empty()) << beside(earlier.dir).front();
}

}  // namespace
}  // namespace systole::test
