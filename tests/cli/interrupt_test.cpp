// A render that fails part-way never touches earlier work. SIGINT or SIGTERM mid-render
// removes the temporary output and exits with 128 + the signal (130, 143); SIGKILL cannot
// clean up, so the next run in that folder does; a full disk fails the run with an I/O
// error. In every case the earlier video and its manifest stay byte for byte as they were.
// And two renders to one output: exactly one writes it.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <gtest/gtest.h>
#include <thread>

#include "support/run.h"

extern char** environ;

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

/// A long render of the heart to `video`, in the background.
struct LongRender {
  pid_t pid = -1;
  fs::path log;
  LongRender(const fs::path& video, const std::vector<std::string>& extra = {}) : log(video.parent_path() / "stderr.txt") {
    std::vector<std::string> args = {SYSTOLE_BINARY, "render", source("scenes/heart.yaml"), "-D", "output.width=160",
                                     "-D", "output.height=120", "-D", "output.duration=60 s", "-o", video.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (posix_spawn(&pid, SYSTOLE_BINARY, &actions, nullptr, argv.data(), environ) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&actions);
  }
  /// Waits until the encoder has written into the temporary file; false if the run ended first.
  bool wait_until_writing(const fs::path& video) {
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (pid > 0 && std::chrono::steady_clock::now() < deadline) {
      const fs::path partial = partial_of(video);
      std::error_code ec;
      if (!partial.empty() && fs::file_size(partial, ec) > 0 && !ec) return true;
      if (int status = 0; ::waitpid(pid, &status, WNOHANG) == pid) {
        pid = -1;
        return false;
      }
      std::this_thread::sleep_for(10ms);
    }
    return false;
  }
  /// Sends `sig` (if given), waits for the exit, and returns the exit code as a shell gives it.
  int finish(int sig = 0) {
    if (pid <= 0) return -1;
    if (sig != 0) ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    pid = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  std::string stderr_text() const { return read_file(log); }
  ~LongRender() {
    finish(SIGKILL);
    std::error_code ec;
    fs::remove(log, ec);
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

/// A small tmpfs mounted at <scratch>/<name>/disk for the life of the object (root only).
struct SmallDisk {
  fs::path dir;
  bool mounted = false;
  SmallDisk(const std::string& name, const std::string& size)
      : dir(fs::path(SYSTOLE_TEST_SCRATCH) / name / "disk") {
    ::umount2(dir.c_str(), MNT_DETACH);  // Left mounted by a run that crashed, if any.
    fs::create_directories(scratch(name) / "disk");
    mounted = ::geteuid() == 0 && ::mount("tmpfs", dir.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
  }
  ~SmallDisk() {
    if (mounted) ::umount2(dir.c_str(), MNT_DETACH);
  }
};

TEST(Interrupt, AFullDiskFailsTheRunAndLeavesTheEarlierVideoAndManifest) {
  const SmallDisk disk("interrupt_full_disk", "1m");
  if (!disk.mounted) GTEST_SKIP() << "cannot mount a small tmpfs here (needs root and mount rights): full disk not tested";
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
