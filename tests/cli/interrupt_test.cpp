// Interrupted runs: SIGINT or SIGTERM mid-render removes the temporary output, leaves the
// earlier output byte for byte as it was, and exits with 128 + the signal (130, 143).

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
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

/// The temporary AtomicOutput writes beside `target` (.<stem>.partial-<pid>-<n><ext>), if any.
fs::path partial_of(const fs::path& target) {
  for (const auto& entry : fs::directory_iterator(target.parent_path())) {
    if (entry.path().filename().string().starts_with("." + target.stem().string() + ".partial-")) return entry.path();
  }
  return {};
}

struct Interrupted {
  int exit_code = -1;
  bool signalled_mid_render = false;  ///< The temporary had data when the signal was sent.
  std::string stderr_text;
};

/// Renders a long clip to `video`, waits until the encoder has written into the temporary
/// file, then sends `sig`.
Interrupted render_and_interrupt(const fs::path& video, int sig) {
  const fs::path log = video.parent_path() / "stderr.txt";
  std::vector<std::string> args = {SYSTOLE_BINARY, "render", source("scenes/heart.yaml"), "-D", "output.width=160",
                                   "-D", "output.height=120", "-D", "output.duration=60 s", "-o", video.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  Interrupted result;
  const int spawned = posix_spawn(&pid, SYSTOLE_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return result;

  // The whole clip takes tens of seconds; frames reach the file within a second or two.
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < deadline) {
    const fs::path partial = partial_of(video);
    std::error_code ec;
    if (!partial.empty() && fs::file_size(partial, ec) > 0 && !ec) {
      result.signalled_mid_render = true;
      break;
    }
    if (::waitpid(pid, nullptr, WNOHANG) == pid) return result;  // Ended before it began: a failure.
    std::this_thread::sleep_for(10ms);
  }
  ::kill(pid, result.signalled_mid_render ? sig : SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.stderr_text = read_file(log);
  fs::remove(log);
  return result;
}

void expect_clean_stop(int sig, int expected_code) {
  const auto dir = scratch("interrupt_" + std::to_string(sig));
  const fs::path video = dir / "clip.mp4";
  const std::string earlier = "an earlier clip that must survive\n";
  write_file(video, earlier);

  const Interrupted r = render_and_interrupt(video, sig);
  ASSERT_TRUE(r.signalled_mid_render) << "the render never wrote its temporary file:\n" << r.stderr_text;
  EXPECT_EQ(r.exit_code, expected_code) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("interrupted; no output was written"), std::string::npos) << r.stderr_text;
  EXPECT_EQ(read_file(video), earlier) << "the earlier output is untouched";
  EXPECT_TRUE(partial_of(video).empty()) << "the temporary file is removed: " << partial_of(video);
}

TEST(Interrupt, SigintMidRenderRemovesTheTemporaryAndExits130) { expect_clean_stop(SIGINT, 130); }

TEST(Interrupt, SigtermMidRenderRemovesTheTemporaryAndExits143) { expect_clean_stop(SIGTERM, 143); }

}  // namespace
}  // namespace systole::test
