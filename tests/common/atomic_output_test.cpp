// AtomicOutput: whole or nothing, one writer per target, and the leftovers of a writer that
// died removed by the next one in the folder. Writers in other processes are real forked
// processes, and "died" is a real SIGKILL.

#include "common/atomic_output.h"
#include "common/interrupt.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "common/error.h"

namespace systole {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("systole_atomic_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Every file in `dir`, by name.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// A writer in another process: it takes `target`, writes into its temporary, tells the
/// parent, and waits to be killed.
struct ForeignWriter {
  pid_t pid = -1;
  explicit ForeignWriter(const fs::path& target) {
    int ready[2];
    EXPECT_EQ(::pipe(ready), 0);
    pid = ::fork();
    if (pid == 0) {
      ::close(ready[0]);
      AtomicOutput out(target);
      write(out.temp_path(), "half a video");
      const char byte = 1;
      [[maybe_unused]] auto n = ::write(ready[1], &byte, 1);
      for (;;) ::pause();
    }
    ::close(ready[1]);
    char byte = 0;
    EXPECT_EQ(::read(ready[0], &byte, 1), 1) << "the writer started";
    ::close(ready[0]);
  }
  void kill_hard() {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    pid = -1;
  }
  ~ForeignWriter() {
    if (pid > 0) kill_hard();
  }
};

TEST(AtomicOutput, CommitReplacesTheTargetAndLeavesNothingElse) {
  const fs::path dir = fresh_dir("commit");
  write(dir / "clip.mp4", "earlier");
  {
    AtomicOutput out(dir / "clip.mp4");
    EXPECT_TRUE(fs::exists(lock_path_of(dir / "clip.mp4"))) << "the lock is held while writing";
    write(out.temp_path(), "new");
    EXPECT_EQ(read(dir / "clip.mp4"), "earlier") << "untouched until commit";
    out.commit();
  }
  EXPECT_EQ(read(dir / "clip.mp4"), "new");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"clip.mp4"}) << "no temporary or lock file is left";
}

TEST(AtomicOutput, WithoutCommitTheEarlierOutputStaysAndNothingIsLeft) {
  const fs::path dir = fresh_dir("abandon");
  write(dir / "clip.mp4", "earlier");
  {
    AtomicOutput out(dir / "clip.mp4");
    write(out.temp_path(), "half");
  }
  EXPECT_EQ(read(dir / "clip.mp4"), "earlier");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"clip.mp4"});
}

TEST(AtomicOutput, AStreamedFileAppearsWholeOnlyWhenItsWriterSucceeds) {
  const fs::path dir = fresh_dir("stream");
  write(dir / "track.wav", "earlier");
  write_atomically(dir / "track.wav", [&](std::ostream& out) {
    out << "RIFF";
    EXPECT_EQ(read(dir / "track.wav"), "earlier") << "untouched while the writer runs";
    out << " and the rest";
  });
  EXPECT_EQ(read(dir / "track.wav"), "RIFF and the rest");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"track.wav"}) << "no temporary or lock file is left";

  write_file_atomically(dir / "captions.vtt", "WEBVTT\n");
  EXPECT_EQ(read(dir / "captions.vtt"), "WEBVTT\n");
}

TEST(AtomicOutput, AThrowingStreamWriterLeavesNoFileAndNoTemporary) {
  const fs::path dir = fresh_dir("stream_throw");
  const auto half_then_throw = [](std::ostream& out) {
    out << "half a file";
    throw Error(ExitCode::kDataError, "the writer gave up");
  };
  EXPECT_THROW(write_atomically(dir / "new.wav", half_then_throw), Error);
  EXPECT_TRUE(names_in(dir).empty()) << ::testing::PrintToString(names_in(dir));
  write(dir / "old.wav", "earlier");
  EXPECT_THROW(write_atomically(dir / "old.wav", half_then_throw), Error);
  EXPECT_EQ(read(dir / "old.wav"), "earlier");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"old.wav"});
}

TEST(AtomicOutput, AStreamedFileInAMissingFolderIsRefusedBeforeItsWriterRuns) {
  const fs::path dir = fresh_dir("stream_missing");
  bool ran = false;
  try {
    write_atomically(dir / "absent" / "a.wav", [&](std::ostream&) { ran = true; });
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kCannotCreate) << e.what();
  }
  EXPECT_FALSE(ran);
  EXPECT_TRUE(names_in(dir).empty());
}

TEST(AtomicOutput, ASecondWriterOfOneTargetIsRefusedWithWhoHoldsIt) {
  const fs::path dir = fresh_dir("busy");
  const fs::path target = dir / "clip.mp4";
  {
    ForeignWriter other(target);
    try {
      AtomicOutput out(target);
      FAIL() << "two writers of one output";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::kBusy);
      const std::string what = e.what();
      EXPECT_NE(what.find("'" + target.string() + "' is being written by another run (pid " + std::to_string(other.pid) + " on "),
                std::string::npos)
          << what;
      EXPECT_NE(what.find("wait for it to finish, or write to another file"), std::string::npos) << what;
    }
    // In one process too (two jobs naming the same file).
    AtomicOutput mine(dir / "other.mp4");
    EXPECT_THROW(AtomicOutput again(dir / "other.mp4"), Error);
  }
  // Another target in the same folder is free all along; this one is once the writer is gone.
  EXPECT_NO_THROW(AtomicOutput(dir / "clip.mp4"));
}

TEST(OutputLock, ARunsClaimIsJoinedByItsWriterAndHeldUntilTheClaimEnds) {
  const fs::path dir = fresh_dir("claim");
  const fs::path target = dir / "clip.mp4";
  {
    const OutputLock claim(target);
    EXPECT_TRUE(fs::exists(lock_path_of(target)));
    {
      AtomicOutput writer(target);  // Joins the claim instead of being refused by it.
      write(writer.temp_path(), "the video");
      // A second writer of the target is still refused, though the claim is this thread's.
      EXPECT_THROW(AtomicOutput again(target), Error);
      writer.commit();
    }
    EXPECT_EQ(read(target), "the video");
    // The writer is done but the run is not: the target is still taken, for another
    // thread (a second job) as for another process.
    std::thread other([&] {
      try {
        OutputLock second(target);
        ADD_FAILURE() << "a claim from another thread was granted";
      } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::kBusy) << e.what();
      }
    });
    other.join();
    EXPECT_TRUE(fs::exists(lock_path_of(target)));
  }
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"clip.mp4"});  // The claim's lock is gone with it.
}

TEST(OutputLock, AClaimOnATargetAnotherProcessWritesIsRefusedAtOnce) {
  const fs::path dir = fresh_dir("claim_busy");
  ForeignWriter other(dir / "clip.mp4");
  try {
    OutputLock claim(dir / "clip.mp4");
    FAIL() << "two runs of one output";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kBusy);
    EXPECT_NE(std::string(e.what()).find("pid " + std::to_string(other.pid)), std::string::npos) << e.what();
  }
  EXPECT_THROW(OutputLock(dir / "absent" / "clip.mp4"), Error) << "a missing folder";
}

TEST(AtomicOutput, LeftoversOfAKilledWriterAreSweptAndALiveWritersAreNot) {
  const fs::path dir = fresh_dir("sweep");
  write(dir / "clip.mp4", "earlier");
  ForeignWriter dead(dir / "clip.mp4");
  ForeignWriter alive(dir / "lungs.mp4");
  dead.kill_hard();
  // What SIGKILL leaves: the temporary and the lock file of each writer, plus a leftover
  // from before outputs were locked.
  write(dir / ".heart.partial-999999-0.mp4", "older format");
  const std::vector<std::string> before = names_in(dir);
  ASSERT_EQ(before.size(), 6u) << ::testing::PrintToString(before);

  EXPECT_EQ(sweep_stale_outputs(dir), 3) << "the dead writer's temporary and lock, and the old leftover";
  const std::vector<std::string> after = names_in(dir);
  ASSERT_EQ(after.size(), 3u) << ::testing::PrintToString(after);
  EXPECT_EQ(after[0], ".lungs.mp4.lock");
  EXPECT_TRUE(after[1].starts_with(".lungs.mp4.partial-")) << after[1];
  EXPECT_EQ(after[2], "clip.mp4");
  EXPECT_EQ(read(dir / "clip.mp4"), "earlier");
  EXPECT_EQ(sweep_stale_outputs(dir), 0) << "a live writer's files stay";
}

TEST(AtomicOutput, TheFirstOutputInAFolderSweepsIt) {
  const fs::path dir = fresh_dir("first");
  {
    ForeignWriter dead(dir / "a.mp4");
    dead.kill_hard();
  }
  ASSERT_EQ(names_in(dir).size(), 2u);
  {
    AtomicOutput out(dir / "b.png");
    write(out.temp_path(), "png");
    out.commit();
  }
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"b.png"});
}

TEST(AtomicOutput, TheSignalHandlerRemovesTemporaryAndLock) {
  const fs::path dir = fresh_dir("signal");
  AtomicOutput out(dir / "clip.mp4");
  write(out.temp_path(), "half");
  remove_pending_outputs_signal_safe();
  EXPECT_TRUE(names_in(dir).empty()) << ::testing::PrintToString(names_in(dir));
}

}  // namespace
}  // namespace systole
