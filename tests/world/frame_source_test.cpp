#include "world/frame_source.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "common/error.h"
#include "scene/load.h"
#include "sim/solvers/step.h"
#include "support/run.h"
#include "world/bake.h"

using namespace systole::test;  // support/run.h

namespace systole::world {
namespace {

scene::Scene heart(const std::string& duration = "0.2 s") {
  return scene::load(test::source("scenes/heart.yaml"), {"output.duration=" + duration});
}

/// Every organ's positions at every clip frame through `last`, stepping a world directly.
std::vector<Eigen::Matrix3Xd> simulated(const scene::Scene& s, int last) {
  World w = build_world(s);
  std::vector<Eigen::Matrix3Xd> frames;
  for (int f = 0; f <= last; ++f) {
    advance_to_frame(w, f);
    frames.emplace_back();
    render_positions(w.organs[0], frames.back());
  }
  return frames;
}

TEST(FrameSource, CallsFrameHooksOnceForEveryFrameInOrderFrameZeroIncluded) {
  FrameSource source(heart());
  std::vector<int> first, second;
  source.on_frame([&](int f) { first.push_back(f); });
  source.on_frame([&](int f) {
    ASSERT_EQ(first.back(), f) << "hooks run in the order they were added";
    second.push_back(f);
  });
  source.advance_to(2);
  source.advance_to(4);
  source.advance_to(3);  // Frames only move forward.
  EXPECT_EQ(first, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(second, first);
  EXPECT_EQ(source.frame(), 4);
}

TEST(FrameSource, GivesTheSimulatedPositionsAndCountsEveryStep) {
  const auto s = heart();
  const std::vector<Eigen::Matrix3Xd> expected = simulated(s, 5);
  FrameSource source(s);
  long long steps_heard = 0;
  source.on_step([&](int organ, const OrganBody& body) {
    EXPECT_EQ(organ, 0);
    EXPECT_GT(body.state.time_s, 0);
    ++steps_heard;
  });
  Eigen::Matrix3Xd x;
  for (int f = 0; f <= 5; ++f) {
    source.advance_to(f);
    source.positions(0, x);
    EXPECT_EQ(x, expected[static_cast<std::size_t>(f)]) << "frame " << f;
  }
  const World& w = source.world();
  EXPECT_EQ(source.steps_taken(), 5LL * w.steps_per_frame * static_cast<long long>(w.organs.size()));
  EXPECT_EQ(steps_heard, source.steps_taken());
}

TEST(FrameSource, SimulatingAheadReplaysTheKeptFramesBitForBitWithoutSteppingAgain) {
  const auto s = heart();
  const std::vector<Eigen::Matrix3Xd> expected = simulated(s, 6);
  FrameSource source(s);
  std::vector<int> frames_heard;
  source.on_frame([&](int f) { frames_heard.push_back(f); });
  source.simulate_ahead(6, {1, 4});
  const long long steps = source.steps_taken();
  EXPECT_EQ(frames_heard, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
  Eigen::Matrix3Xd x;
  source.advance_to(1);
  source.positions(0, x);
  EXPECT_EQ(x, expected[1]);
  source.advance_to(4);
  source.positions(0, x);
  EXPECT_EQ(x, expected[4]);
  EXPECT_EQ(source.steps_taken(), steps) << "a replay takes no step";
  EXPECT_EQ(frames_heard.size(), 7u) << "a replay calls no frame hook again";
  source.advance_to(5);
  EXPECT_THROW(source.positions(0, x), Error) << "frame 5 was not kept";
}

TEST(FrameSource, ReplaysABakeAsTheSimulationMadeIt) {
  const auto s = heart();
  const std::vector<Eigen::Matrix3Xd> expected = simulated(s, s.output.frame_count() - 1);
  const auto dir = scratch("frame_source_bake");
  {
    FrameSource writer_source(s);
    BakeWriter writer(dir / "h.bake", s, writer_source.world());
    writer_source.on_frame([&](int) {
      Eigen::Matrix3Xd x;
      for (std::size_t o = 0; o < writer_source.world().organs.size(); ++o) {
        writer_source.positions(static_cast<int>(o), x);
        writer.write(x);
      }
    });
    writer_source.advance_to(s.output.frame_count() - 1);
    writer.commit();
  }
  FrameSource source(s);
  source.replay_bake(dir / "h.bake", s);
  EXPECT_TRUE(source.replays_bake());
  std::vector<Eigen::Matrix3Xd> heard;
  source.on_frame([&](int) {
    heard.emplace_back();
    source.positions(0, heard.back());
  });
  source.advance_to(s.output.frame_count() - 1);
  EXPECT_EQ(source.steps_taken(), 0);
  ASSERT_EQ(heard.size(), expected.size());
  for (std::size_t f = 0; f < heard.size(); ++f) EXPECT_EQ(heard[f], expected[f]) << "frame " << f;
}

TEST(FrameSource, ACancelledRunStopsBetweenFramesWithInterrupted) {
  FrameSource source(heart());
  std::atomic<bool> cancel{false};
  source.set_cancel(&cancel);
  source.on_frame([&](int f) {
    if (f == 2) cancel = true;
  });
  try {
    source.advance_to(5);
    FAIL() << "the run went on after the cancel";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kInterrupted);
  }
  EXPECT_EQ(source.frame(), 2) << "stopped before frame 3";
}

TEST(FrameSource, StackedPositionsAreEveryOrganInOrder) {
  const auto s = scene::load(test::source("scenes/chest.yaml"), {"output.duration=0.1 s"});
  FrameSource source(s);
  source.advance_to(1);
  Eigen::Matrix3Xd all, one;
  source.stacked_positions(all);
  Eigen::Index at = 0;
  for (std::size_t o = 0; o < source.world().organs.size(); ++o) {
    source.positions(static_cast<int>(o), one);
    ASSERT_LE(at + one.cols(), all.cols());
    EXPECT_EQ(all.middleCols(at, one.cols()), one) << "organ " << o;
    at += one.cols();
  }
  EXPECT_EQ(at, all.cols());
  EXPECT_GE(source.world().organs.size(), 2u);
}

TEST(BodyPlayback, StepsTheModelAsSimStepDoesAndCallsBackAfterEveryStep) {
  World w = build_world(heart());
  const sim::Model& model = w.organs[0].model;
  sim::State by_hand = sim::initial_state(model);
  for (int k = 0; k < 7; ++k) sim::step(model, by_hand, w.dt_s);
  BodyPlayback playback(model, w.dt_s);
  std::vector<int> heard;
  playback.run(3, [&](int k) { heard.push_back(k); });
  playback.run(4);
  EXPECT_EQ(heard, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(playback.state().x, by_hand.x);
  EXPECT_DOUBLE_EQ(playback.state().time_s, by_hand.time_s);
}

}  // namespace
}  // namespace systole::world
