// ctest-labels: slow-under-sanitizers
// Issue 37's round trip on a shipped anatomical heart with hand-timed delays (heart-cutaway:
// heart's body and blood, without its conduction system), with its blood and without: the
// scene's clip exported as a point cache is its own target, the known drives play it back
// within the key frames' interpolation, and drives perturbed by 30 % in amplitude and 40 ms
// in delay (each waveform and stiffness kept, `lock: [shape, stiffness]`) are tuned back to
// it: within 10 % of its motion, every amplitude within 10 % and every delay within 10 ms
// (issue 37, acceptance 1). About 100 s each on two cores: 500 playbacks, where the search
// needs them (at 150 it ends at 13-22 %, the atria's drives still wrong; docs/training.md).

#include <gtest/gtest.h>

#include <cmath>

#include "support/run.h"
#include "heart_clip_target.h"
#include "train_test_util.h"

namespace systole {
namespace {

using train::testing::printed_pct;
using train::testing::replace_once;
using train::testing::with_own_clip_as_target;
using train::testing::tuned_value;

struct Drive {
  const char* region;
  double amplitude, delay_s;  // The scene's. unit: 1, s
};
// scenes/heart-cutaway.yaml's drives, in order (the atria's delay is 0).
constexpr Drive kDrives[] = {{"left_atrium", 0.10, 0}, {"right_atrium", 0.10, 0}, {"left_ventricle", 0.24, 0.160},
                             {"right_ventricle", 0.23, 0.160}, {"apex", 0.45, 0.160}};

/// The delay's distance on the beat's circle (delays wrap at the period). unit: s
double delay_apart(double a_s, double b_s) {
  const double period_s = 60.0 / 72.0;
  return std::abs(std::remainder(a_s - b_s, period_s));
}

void round_trip(const std::string& name, bool blood) {
  const auto dir = test::scratch("anatomical_round_trip_" + name);
  std::string scene = test::read_file(test::source("scenes/heart-cutaway.yaml"));
  if (!blood) {
    const std::size_t line = scene.find("    blood:");
    ASSERT_NE(line, std::string::npos);
    scene.erase(line, scene.find('\n', line) + 1 - line);
  }
  scene = with_own_clip_as_target(dir, scene, "shape, stiffness", 500);
  // +-30 % in amplitude, +-40 ms or more in delay.
  replace_once(scene, "amplitude: 0.10, systolic_fraction: 0.15}", "amplitude: 0.13, delay: 40 ms, systolic_fraction: 0.15}");
  replace_once(scene, "amplitude: 0.10, systolic_fraction: 0.15}", "amplitude: 0.07, delay: 40 ms, systolic_fraction: 0.15}");
  replace_once(scene, "amplitude: 0.24, delay: 160 ms", "amplitude: 0.31, delay: 200 ms");
  replace_once(scene, "amplitude: 0.23, delay: 160 ms", "amplitude: 0.16, delay: 120 ms");
  replace_once(scene, "amplitude: 0.45, delay: 160 ms", "amplitude: 0.585, delay: 205 ms");
  test::write_file(dir / "tune.yaml", scene);
  const auto tuned = test::run(test::systole() + " tune " + (dir / "tune.yaml").string() + " -o " + (dir / "t.yaml").string() +
                               " --jobs 2 --report " + (dir / "report").string());
  ASSERT_EQ(tuned.exit_code, 0) << tuned.output;
  const double error = printed_pct(tuned.output, "tuned");
  std::printf("%s: tuned to %.2f %% of the target's motion (perturbed: %.1f %%)\n", name.c_str(), error,
              printed_pct(tuned.output, "as written"));
  EXPECT_LT(error, 10.0) << tuned.output;
  const std::string report = test::read_file(dir / "report" / "report.md");
  for (const Drive& d : kDrives) {
    SCOPED_TRACE(d.region);
    EXPECT_NEAR(tuned_value(report, std::string(d.region) + ".amplitude"), d.amplitude, 0.1 * d.amplitude) << report;
    EXPECT_LT(delay_apart(tuned_value(report, std::string(d.region) + ".delay"), d.delay_s), 0.010) << report;
  }
}

TEST(AnatomicalRoundTrip, TheHeartWithItsBloodIsTunedBackToItsDrives) { round_trip("blood", true); }

TEST(AnatomicalRoundTrip, TheHeartWithoutBloodIsTunedBackToItsDrives) { round_trip("no_blood", false); }

}  // namespace
}  // namespace systole
