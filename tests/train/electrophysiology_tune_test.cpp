// ctest-labels: slow-under-sanitizers
// `tune` on a heart timed by its conduction system (issue 40): the activation is the
// conduction model's, so only the regions' amplitudes (and shapes, where free) are tuned.
// scenes/heart-conduction.yaml's clip, exported as a point cache, is its own target; its
// drives perturbed by 30 % in amplitude (waveforms and stiffness kept) are tuned back within
// 10 % of its motion and 10 % of each amplitude, and the tuned scene writes no delay (which
// an organ with `electrophysiology` refuses) and loads. About 35 s on two cores.

#include <gtest/gtest.h>

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
  double amplitude;  // The scene's. unit: 1
};
// scenes/heart-conduction.yaml's drives, in order.
constexpr Drive kDrives[] = {
    {"left_atrium", 0.10}, {"right_atrium", 0.10}, {"left_ventricle", 0.24}, {"right_ventricle", 0.23}, {"apex", 0.45}};

TEST(ElectrophysiologyTune, KeepsTheConductionsTimingAndTunesTheAmplitudesBack) {
  const auto dir = test::scratch("electrophysiology_tune");
  std::string scene = test::read_file(test::source("scenes/heart-conduction.yaml"));
  scene = with_own_clip_as_target(dir, scene, "shape, stiffness", 150);
  replace_once(scene, "amplitude: 0.10,", "amplitude: 0.13,");
  replace_once(scene, "amplitude: 0.10,", "amplitude: 0.07,");
  replace_once(scene, "amplitude: 0.24,", "amplitude: 0.31,");
  replace_once(scene, "amplitude: 0.23,", "amplitude: 0.16,");
  replace_once(scene, "amplitude: 0.45,", "amplitude: 0.585,");
  test::write_file(dir / "tune.yaml", scene);
  const auto tuned = test::run(test::systole() + " tune " + (dir / "tune.yaml").string() + " -o " + (dir / "t.yaml").string() +
                               " --jobs 2 --report " + (dir / "report").string());
  ASSERT_EQ(tuned.exit_code, 0) << tuned.output;
  const double error = printed_pct(tuned.output, "tuned");
  std::printf("tuned to %.2f %% of the target's motion (perturbed: %.1f %%)\n", error, printed_pct(tuned.output, "as written"));
  EXPECT_LT(error, 10.0) << tuned.output;
  const std::string report = test::read_file(dir / "report" / "report.md");
  for (const Drive& d : kDrives) {
    SCOPED_TRACE(d.region);
    EXPECT_NEAR(tuned_value(report, std::string(d.region) + ".amplitude"), d.amplitude, 0.1 * d.amplitude) << report;
    EXPECT_EQ(report.find(std::string("| ") + d.region + ".delay"), std::string::npos) << "no delay is searched";
  }
  const std::string written = test::read_file(dir / "t.yaml");
  EXPECT_EQ(written.find("delay"), std::string::npos) << written;
  const auto loads = test::run(test::systole() + " validate " + (dir / "t.yaml").string());
  EXPECT_EQ(loads.exit_code, 0) << loads.output;
}

}  // namespace
}  // namespace systole
