// Nothing invisible passes silently: a camera with no position frames the organs, whatever
// their size, and a first frame that would show no organ is an error naming the cause.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "encode/png.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

/// An octahedron-sphere of `radius` (file units) as OBJ text: closed, outward.
std::string ball_obj(double radius) {
  std::string obj;
  const int rings = 12, segments = 24;
  char line[128];
  std::snprintf(line, sizeof line, "v 0 %.9g 0\n", radius);
  obj += line;
  for (int r = 1; r < rings; ++r) {
    const double theta = M_PI * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * M_PI * s / segments;
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", radius * std::sin(theta) * std::cos(phi),
                    radius * std::cos(theta), -radius * std::sin(theta) * std::sin(phi));
      obj += line;
    }
  }
  std::snprintf(line, sizeof line, "v 0 %.9g 0\n", -radius);
  obj += line;
  const auto at = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) obj += "f 1 " + std::to_string(at(1, s)) + " " + std::to_string(at(1, s + 1)) + "\n";
  for (int r = 1; r < rings - 1; ++r) {
    for (int s = 0; s < segments; ++s) {
      obj += "f " + std::to_string(at(r, s)) + " " + std::to_string(at(r + 1, s)) + " " + std::to_string(at(r + 1, s + 1)) + "\n";
      obj += "f " + std::to_string(at(r, s)) + " " + std::to_string(at(r + 1, s + 1)) + " " + std::to_string(at(r, s + 1)) + "\n";
    }
  }
  const int last = 2 + (rings - 1) * segments;
  for (int s = 0; s < segments; ++s) {
    obj += "f " + std::to_string(last) + " " + std::to_string(at(rings - 1, s + 1)) + " " + std::to_string(at(rings - 1, s)) + "\n";
  }
  return obj;
}

/// A folder with ball.obj of `radius` metres and scene.yaml showing it with `camera`.
fs::path ball_scene(const std::string& name, double radius, const std::string& camera = "") {
  const fs::path dir = scratch(name);
  write_file(dir / "ball.obj", ball_obj(radius));
  write_file(dir / "scene.yaml", "organs:\n  - name: ball\n    mesh: {file: ball.obj, units: m}\n" + camera +
                                     "output: {width: 160, height: 120, duration: 0.1 s}\n");
  return dir;
}

/// The share of the first frame's pixels that are not background.
double covered_share(const fs::path& dir) {
  const RunResult r = run(systole() + " render " + (dir / "scene.yaml").string() + " --frames 0 --no-video --png " +
                          (dir / "frames").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const Image image = encode::read_png(dir / "frames" / "frame_00000.png");
  const auto* bg = image.pixel(0, 0);
  int covered = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      covered += std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 12;
    }
  }
  return double(covered) / (image.width * image.height);
}

TEST(CameraFraming, AnOrganOfOneCentimetreAndOneOfOneMetreFillTheFrameAlike) {
  const double small = covered_share(ball_scene("framing_1cm", 0.005));
  const double large = covered_share(ball_scene("framing_1m", 0.5));
  // A sphere filling 0.8 of the frame's height: pi (0.4 x 120)^2 / (160 x 120) = 0.38.
  EXPECT_NEAR(small, 0.38, 0.06);
  EXPECT_NEAR(large, small, 0.01) << "the same picture at any size";
  // Without the framing, the old fixed camera (0.4 m away) saw the 1 cm ball as a speck.
  const double fixed = covered_share(ball_scene("framing_fixed", 0.005, "camera: {position: [0, 0, 0.4]}\n"));
  EXPECT_LT(fixed, 0.01);
  // `camera: auto` says the same explicitly, and `fill` sets the share.
  EXPECT_NEAR(covered_share(ball_scene("framing_auto", 0.5, "camera: auto\n")), large, 1e-9);
  EXPECT_NEAR(covered_share(ball_scene("framing_fill", 0.5, "camera: {fill: 0.4}\n")), large / 4, 0.02);
}

void expect_unseen(const std::string& name, double radius, const std::string& camera, const std::string& cause) {
  SCOPED_TRACE(name);
  const fs::path dir = ball_scene(name, radius, camera);
  for (const std::string& command : {" validate " + (dir / "scene.yaml").string(),
                                     " render " + (dir / "scene.yaml").string() + " -o " + (dir / "clip.mp4").string()}) {
    const RunResult r = run(systole() + command);
    EXPECT_EQ(r.exit_code, 65) << r.output;
    EXPECT_NE(r.output.find("scene.yaml: no organ would be seen in the first frame"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("organ 'ball': " + cause), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "clip.mp4")) << "no video of empty background";
  }
}

TEST(CameraFraming, AFirstFrameWithNoOrganIsAnErrorNamingTheCause) {
  expect_unseen("unseen_behind", 0.05, "camera: {position: [0, 0, -0.5], target: [0, 0, -1]}\n",
                "it is behind the camera (the organ is around (0, 0, 0) m, the camera at (0, 0, -0.5) m looks at (0, 0, -1) m)");
  expect_unseen("unseen_aside", 0.05, "camera: {position: [0, 0, 0.5], target: [3, 0, 0.5]}\n",
                "it is outside the view");
  expect_unseen("unseen_small", 0.005, "camera: {position: [0, 0, 2000]}\n", "it is too small to cover a pixel");
}

}  // namespace
}  // namespace systole::test
