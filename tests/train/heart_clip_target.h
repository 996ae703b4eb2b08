#pragma once
// Shared by the anatomical heart's training round trips: a shipped heart's own clip as the
// target it is tuned back to.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run.h"

namespace systole::train::testing {

inline void replace_once(std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

/// Writes `scene` (a shipped anatomical heart) to dir/heart.yaml, exports its 2.5-s clip at
/// 90 frames a second as dir/heart.pc2 (at 30 the key frames' interpolation of the valves'
/// leaflets, which open within a frame, alone is 12 % of the motion: docs/training.md), and
/// returns `scene` with that clip as its heart's target: three cycles, `lock` and `budget`
/// as given. A failed export fails the test.
inline std::string with_own_clip_as_target(const std::filesystem::path& dir, std::string scene, const std::string& lock,
                                           int budget) {
  test::write_file(dir / "heart.yaml", scene);
  const auto exported = test::run(test::systole() + " export " + (dir / "heart.yaml").string() + " -o " +
                                  (dir / "heart.pc2").string() + " -D output.duration=2.5s -D output.fps=90");
  EXPECT_EQ(exported.exit_code, 0) << exported.output;
  const std::string coronaries = "      - {name: coronary_arteries, color: \"#d9a441\"}\n";
  replace_once(scene, coronaries,
               coronaries + "    target: {rate: 72 bpm, animation: heart.pc2, cycles: 3, lock: [" + lock +
                   "], budget: " + std::to_string(budget) + "}\n");
  return scene;
}

}  // namespace systole::train::testing
