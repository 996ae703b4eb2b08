// FolderUpdate: staged files replace their namesakes in a folder together at commit, or
// not at all; the folder's other files are never touched; a commit killed part-way is
// finished by the next update of the folder, and what dead runs left is removed by it.
// Runs that die are real forked processes, and "died" is a real SIGKILL (or SIGTERM through
// a handler like the command line's).

#include "common/folder_update.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/interrupt.h"
#include "support/small_disk.h"

namespace systole {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(SYSTOLE_TEST_SCRATCH) / ("folder_update_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

/// Every file under `dir` with its contents, by path relative to `dir` ("sub/" for a folder).
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(e.path(), dir).string();
    if (e.is_directory()) {
      files[name + "/"] = "";
    } else {
      std::ifstream in(e.path(), std::ios::binary);
      files[name] = {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
  }
  return files;
}

/// The names in `dir`, sorted.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string frame(int i) { return "frame_" + std::to_string(i) + ".png"; }

/// A folder as an earlier run and its user left it: frames 0-9, a note, a subfolder.
fs::path earlier_folder(const fs::path& dir) {
  const fs::path folder = dir / "frames";
  fs::create_directories(folder / "sub");
  for (int i = 0; i < 10; ++i) write(folder / frame(i), "old " + std::to_string(i));
  write(folder / "notes.txt", "keep me");
  write(folder / "sub" / "inner.txt", "keep me too");
  return folder;
}

/// `before` with frames [0, n) new, as stage() writes them.
std::map<std::string, std::string> with_new_frames(std::map<std::string, std::string> before, int n) {
  for (int i = 0; i < n; ++i) before[frame(i)] = "new " + std::to_string(i);
  return before;
}

void stage(const FolderUpdate& update, int n) {
  for (int i = 0; i < n; ++i) write(update.staged_path(frame(i)), "new " + std::to_string(i));
}

/// Runs `body` in a forked child that exits 0 after it (99 if it throws); returns the
/// child's wait status.
int in_child(const std::function<void()>& body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    try {
      body();
    } catch (...) {
      ::_exit(99);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(FolderUpdate, CommitReplacesTheStagedFilesTogetherAndNothingElse) {
  const fs::path dir = fresh_dir("commit");
  const fs::path folder = earlier_folder(dir);
  const auto before = contents(folder);
  {
    FolderUpdate update(folder);
    stage(update, 4);
    EXPECT_EQ(contents(folder), before) << "nothing lands before the commit";
    EXPECT_EQ(names_in(dir).size(), 3u) << "the folder, its lock and the staging folder beside it";
    update.commit();
    EXPECT_EQ(contents(folder), with_new_frames(before, 4));
  }
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"frames"}) << "no staging folder, journal or lock is left";
}

TEST(FolderUpdate, WithoutCommitTheFolderStaysAsItWas) {
  const fs::path dir = fresh_dir("no_commit");
  const fs::path folder = earlier_folder(dir);
  const auto before = contents(folder);
  {
    FolderUpdate update(folder);
    stage(update, 10);
  }
  EXPECT_EQ(contents(folder), before);
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"frames"});
}

TEST(FolderUpdate, ANewFolderAppearsWholeAtCommit) {
  const fs::path dir = fresh_dir("new");
  const fs::path folder = dir / "a" / "frames";
  FolderUpdate update(dir / "a" / "frames/");  // Parents made; a trailing '/' names the same folder.
  EXPECT_EQ(update.folder(), folder);
  stage(update, 3);
  EXPECT_FALSE(fs::exists(folder)) << "made only at the commit";
  update.commit();
  EXPECT_EQ(contents(folder), with_new_frames({}, 3));
}

TEST(FolderUpdate, ACommitKilledPartWayIsFinishedByTheNextUpdate) {
  const fs::path dir = fresh_dir("killed_commit");
  const fs::path folder = earlier_folder(dir);
  const auto before = contents(folder);
  const int status = in_child([&] {
    FolderUpdate update(folder);
    stage(update, 10);
    update.commit([](int moved) {
      if (moved == 4) ::raise(SIGKILL);
    });
  });
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
  // Killed after the journal: a mix of new and old frames, finishable.
  ASSERT_TRUE(fs::exists(journal_path_of(folder)));
  auto mixed = before;
  for (int i = 0; i < 4; ++i) mixed[frame(i)] = "new " + std::to_string(i);
  EXPECT_EQ(contents(folder), mixed);
  {
    const FolderUpdate next(folder);  // Finishes it first.
    EXPECT_EQ(contents(folder), with_new_frames(before, 10));
    EXPECT_FALSE(fs::exists(journal_path_of(folder)));
    EXPECT_EQ(names_in(dir).size(), 3u) << ::testing::PrintToString(names_in(dir)) << ": only the folder, and the "
                                        << "next update's own lock and staging folder";
  }
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"frames"});
}

TEST(FolderUpdate, AWriterKilledBeforeItsCommitLeavesTheFolderAndTheNextUpdateRemovesItsStaging) {
  const fs::path dir = fresh_dir("killed_writer");
  const fs::path folder = earlier_folder(dir);
  const auto before = contents(folder);
  const int status = in_child([&] {
    FolderUpdate update(folder);
    stage(update, 6);
    ::raise(SIGKILL);
  });
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
  EXPECT_EQ(contents(folder), before);
  EXPECT_EQ(names_in(dir).size(), 3u) << "what SIGKILL leaves: the staging folder and the lock file";
  { const FolderUpdate next(folder); }
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"frames"});
  EXPECT_EQ(contents(folder), before);
}

TEST(FolderUpdate, AJournalCutShortMeansNothingHadMoved) {
  const fs::path dir = fresh_dir("cut_journal");
  const fs::path folder = earlier_folder(dir);
  const auto before = contents(folder);
  // A run killed while writing its journal: the name without its newline.
  fs::create_directory(dir / ".frames.staging-999999-0");
  write(dir / ".frames.staging-999999-0" / frame(0), "new 0");
  write(journal_path_of(folder), ".frames.staging-999999-0");
  { const FolderUpdate next(folder); }
  EXPECT_EQ(contents(folder), before);
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"frames"});
}

// The command line's handler (cli/main.cpp), reporting what it would say on a pipe.
int g_report_fd = -1;
extern "C" void report_and_exit(int sig) {
  if (interrupt_deferred_signal_safe(sig)) return;
  remove_pending_outputs_signal_safe();
  const std::string_view written = outputs_written_signal_safe();
  [[maybe_unused]] auto n = ::write(g_report_fd, written.data(), written.size());
  ::_exit(128 + sig);
}

/// Runs `body` in a child with that handler for SIGTERM; returns its exit code and report.
std::pair<int, std::string> interrupted_child(const std::function<void()>& body) {
  int report[2];
  EXPECT_EQ(::pipe(report), 0);
  const int status = in_child([&] {
    ::close(report[0]);
    g_report_fd = report[1];
    struct sigaction action {};
    action.sa_handler = report_and_exit;
    action.sa_flags = SA_RESTART;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGTERM, &action, nullptr);
    body();
  });
  ::close(report[1]);
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = ::read(report[0], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
  ::close(report[0]);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), text};
}

TEST(FolderUpdate, SigtermDuringTheCommitWaitsForItAndThenNamesTheFolder) {
  const fs::path dir = fresh_dir("term_in_commit");
  const fs::path folder = earlier_folder(dir);
  const auto before = contents(folder);
  const auto [code, written] = interrupted_child([&] {
    FolderUpdate update(folder);
    stage(update, 10);
    update.commit([](int moved) {
      if (moved == 2) ::kill(::getpid(), SIGTERM);
    });
    ::_exit(0);  // Not reached: the signal is raised again when the commit ends.
  });
  EXPECT_EQ(code, 143);
  EXPECT_NE(written.find("'" + folder.string() + "'"), std::string::npos) << written;
  EXPECT_EQ(contents(folder), with_new_frames(before, 10)) << "the commit ran to its end";
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"frames"});
}

TEST(FolderUpdate, SigtermBeforeTheCommitRemovesTheStagingFolderAndSaysNothingWasWritten) {
  const fs::path dir = fresh_dir("term_in_staging");
  const fs::path folder = earlier_folder(dir);
  const auto before = contents(folder);
  const auto [code, written] = interrupted_child([&] {
    FolderUpdate update(folder);
    stage(update, 10);
    ::kill(::getpid(), SIGTERM);
  });
  EXPECT_EQ(code, 143);
  EXPECT_EQ(written.find(folder.string()), std::string::npos) << written;
  EXPECT_EQ(contents(folder), before);
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"frames"}) << "the handler removed the staging folder and lock";
}

TEST(FolderUpdate, ASecondUpdateOfTheFolderIsRefusedAndARunsClaimIsJoined) {
  const fs::path dir = fresh_dir("busy");
  const fs::path folder = earlier_folder(dir);
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t other = ::fork();
  if (other == 0) {
    const FolderUpdate update(folder);
    const char byte = 1;
    [[maybe_unused]] auto n = ::write(ready[1], &byte, 1);
    for (;;) ::pause();
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  try {
    FolderUpdate second(folder);
    ADD_FAILURE() << "two updates of one folder";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kBusy) << e.what();
  }
  ::kill(other, SIGKILL);
  ::waitpid(other, nullptr, 0);
  const OutputLock claim(update_folder_of(folder));  // A run's claim, as render_clip takes it.
  EXPECT_NO_THROW(FolderUpdate(folder / "")) << "its writer joins it";
}

TEST(FolderUpdate, FolderNames) {
  EXPECT_EQ(update_folder_of("frames/"), fs::path("frames"));
  EXPECT_EQ(update_folder_of("out/frames//"), fs::path("out/frames"));
  EXPECT_EQ(update_folder_of("."), fs::current_path());
  EXPECT_EQ(update_folder_of("./"), fs::current_path());
  EXPECT_THROW(update_folder_of("/"), Error);
  EXPECT_THROW(update_folder_of(""), Error);
  const fs::path dir = fresh_dir("names");
  fs::create_directory(dir / "real");
  fs::create_directory_symlink(dir / "real", dir / "link");
  EXPECT_EQ(update_folder_of(dir / "link"), fs::canonical(dir / "real")) << "its staging folder goes beside the real one";
}

TEST(FolderUpdate, AFileInTheWayIsRefusedBeforeAnythingMoves) {
  const fs::path dir = fresh_dir("in_the_way");
  write(dir / "file", "x");
  EXPECT_THROW(FolderUpdate(dir / "file"), Error);
  const fs::path folder = earlier_folder(dir);
  fs::remove(folder / frame(5));
  fs::create_directory(folder / frame(5));  // A folder with a staged file's name.
  const auto before = contents(folder);
  FolderUpdate update(folder);
  stage(update, 10);
  try {
    update.commit();
    ADD_FAILURE() << "a file renamed over a folder";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kCannotCreate) << e.what();
  }
  EXPECT_EQ(contents(folder), before);
  EXPECT_FALSE(fs::exists(journal_path_of(folder)));
}

TEST(FolderUpdate, AMountPointIsStagedInsideItself) {
  const fs::path dir = fresh_dir("mount");
  const test::SmallDisk disk(dir / "frames", "1m");
  if (!disk.mounted) GTEST_SKIP() << test::kNoSmallDisk;
  write(disk.dir / "notes.txt", "keep me");
  const auto before = contents(disk.dir);
  FolderUpdate update(disk.dir);
  stage(update, 3);
  // Beside it a rename would cross file systems (EXDEV) at the commit, after the whole run.
  EXPECT_EQ(names_in(disk.dir).size(), 2u) << ::testing::PrintToString(names_in(disk.dir));
  update.commit();
  EXPECT_EQ(contents(disk.dir), with_new_frames(before, 3));
}

}  // namespace
}  // namespace systole
