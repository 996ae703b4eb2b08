// ctest-labels: slow-under-sanitizers
// `systole export` end to end: the frames encoding holds the simulated positions (as a bake
// stores them at full precision) to float32 rounding, the compact loop reports its error
// within the budget, a still organ is called still, a scene that cannot loop is refused with the reason, and a failed
// export leaves no file behind.

#include <gtest/gtest.h>

#include <cstring>
#include <regex>
#include <tiny_gltf.h>

#include "mesh/gltf_read.h"
#include "world/bake.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

const std::string kHeart = source("scenes/heart.yaml");
const std::string kShort = " -D 'output.duration=0.4 s' ";

tinygltf::Model load_glb(const fs::path& file) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  // From memory: Debian's libtinygltf crashes reading a file itself (its default file
  // callbacks), and reading from memory is what the other tests do.
  const std::string bytes = read_file(file);
  EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                          static_cast<unsigned>(bytes.size())))
      << err;
  return model;
}

Eigen::Matrix3Xd positions(const tinygltf::Model& m, int accessor) {
  const auto& a = m.accessors[static_cast<std::size_t>(accessor)];
  const auto& view = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
  Eigen::Matrix3Xf x(3, static_cast<Eigen::Index>(a.count));
  std::memcpy(x.data(), m.buffers[0].data.data() + view.byteOffset + a.byteOffset, sizeof(float) * 3 * a.count);
  return x.cast<double>();
}

/// Only the given names in `dir` (no temporaries, no locks, no partial output).
std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ExportCommand, EveryFrameAsAMorphTargetIsTheSimulationToFloatRounding) {
  const auto dir = scratch("export_frames");
  auto r = run(systole() + " bake " + kHeart + kShort + "-o " + (dir / "h.bake").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run(systole() + " export " + kHeart + kShort + "--encoding frames -o " + (dir / "h.glb").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("every frame a morph target, 12 frames"), std::string::npos) << r.output;
  const auto m = load_glb(dir / "h.glb");
  world::BakeReader bake(dir / "h.bake");
  const auto& prim = m.meshes.at(0).primitives.at(0);
  ASSERT_EQ(prim.targets.size(), std::size_t(bake.info().frame_count));
  const Eigen::Matrix3Xd base = positions(m, prim.attributes.at("POSITION"));
  Eigen::Matrix3Xd simulated;
  double worst = 0, moved = 0;
  for (int f = 0; f < bake.info().frame_count; ++f) {
    bake.read(f, 0, simulated);
    const Eigen::Matrix3Xd shown = base + positions(m, prim.targets[static_cast<std::size_t>(f)].at("POSITION"));
    worst = std::max(worst, (shown - simulated).cwiseAbs().maxCoeff());
    if (f > 0) {
      Eigen::Matrix3Xd first;
      bake.read(0, 0, first);
      moved = std::max(moved, (simulated - first).cwiseAbs().maxCoeff());
    }
  }
  // The heart is under 10 cm across: two float32 roundings are below 1e-8 m.
  EXPECT_LT(worst, 2e-8) << "max coordinate difference from the simulation, m";
  EXPECT_GT(moved, 1e-4) << "the heart moves, so a wrong frame would show";
  // Read back as a target: 12 frames of a clip that does not loop last 12 frame times (as
  // its point cache does), sampled at the frames themselves.
  const auto clip = mesh::read_gltf_morphs(dir / "h.glb", 0, 1, 0);
  ASSERT_TRUE(clip.has_value());
  EXPECT_NEAR(clip->duration, 0.4, 1e-6);
  ASSERT_EQ(clip->poses.size(), 12u);
  for (int f = 0; f < 12; ++f) {
    Eigen::Matrix3Xd frame;
    bake.read(f, 0, frame);
    double apart = 0;
    for (std::size_t v = 0; v < clip->poses[static_cast<std::size_t>(f)].size(); ++v) {
      apart = std::max(apart, (clip->poses[static_cast<std::size_t>(f)][v] - Eigen::Vector3d(frame.col(static_cast<Eigen::Index>(v)))).norm());
    }
    EXPECT_LT(apart, 1e-7) << "frame " << f;
  }
  // From the bake, the same bytes.
  r = run(systole() + " export " + kHeart + kShort + "--encoding frames --from-bake " + (dir / "h.bake").string() +
          " -o " + (dir / "b.glb").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_file(dir / "b.glb"), read_file(dir / "h.glb"));
}

TEST(ExportCommand, TheCompactLoopReportsItsErrorWithinTheBudget) {
  const auto dir = scratch("export_compact");
  const auto r = run(systole() + " export " + kHeart + " -o " + (dir / "h.glb").string() + " --max-error 2%");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(heart: (\d+) morph targets, error ([0-9.e+-]+) %)"))) << r.output;
  EXPECT_GE(std::stoi(m[1]), 4);
  EXPECT_LE(std::stoi(m[1]), 16);
  EXPECT_LE(std::stod(m[2]), 2.0);
  EXPECT_LT(fs::file_size(dir / "h.glb"), 2'000'000u);
  const auto model = load_glb(dir / "h.glb");
  ASSERT_EQ(model.animations.size(), 1u);
  EXPECT_EQ(listing(dir), std::vector<std::string>{"h.glb"}) << "no lock or temporary left";
}

TEST(ExportCommand, AStillOrganIsReportedStillNotAsAShareOfNoMotion) {
  const auto dir = scratch("export_still");
  const auto r = run(systole() + " export " + source("scenes/liver.yaml") + kShort +
                     "-D 'interactions=[]' --encoding frames -o " + (dir / "l.glb").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("liver: 12 morph targets, still (no motion to reproduce)"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("% of the motion"), std::string::npos) << r.output;
}

/// The numbers in the page's camera, in order: position, target, up, fov_deg.
std::vector<double> page_camera(const fs::path& page) {
  const std::string text = read_file(page);
  std::smatch m;
  const std::regex json(R"(<script id="camera" type="application/json">(.*)</script>)");
  if (!std::regex_search(text, m, json)) return {};
  const std::string body = m[1];
  std::vector<double> v;
  const std::regex number(R"(-?[0-9][0-9.e+-]*)");
  for (auto it = std::sregex_iterator(body.begin(), body.end(), number); it != std::sregex_iterator(); ++it) {
    v.push_back(std::stod(it->str()));
  }
  return v;
}

TEST(ExportCommand, ThePageOpensOnTheCameraTheVideoIsSeenFrom) {
  const auto dir = scratch("export_page_camera");
  // The scene's own camera (scenes/heart.yaml: at (0, 0.01, 0.34) looking at the origin, 40 deg).
  auto r = run(systole() + " export " + kHeart + " -o " + (dir / "h.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The report says which simulated frames the loop is: after whole loops of settling.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(compact loop of (\d+) frames .*simulated frames (\d+) to (\d+)\))")))
      << r.output;
  EXPECT_GT(std::stoi(m[2]), 0);
  EXPECT_EQ(std::stoi(m[2]) % std::stoi(m[1]), 0) << "settling is whole loops";
  EXPECT_EQ(std::stoi(m[3]) - std::stoi(m[2]) + 1, std::stoi(m[1]));
  auto v = page_camera(dir / "h.html");
  ASSERT_EQ(v.size(), 10u);
  EXPECT_NEAR(v[0], 0, 1e-12);
  EXPECT_NEAR(v[1], 0.01, 1e-12);
  EXPECT_NEAR(v[2], 0.34, 1e-12);
  EXPECT_NEAR(v[3] * v[3] + v[4] * v[4] + v[5] * v[5], 0, 1e-20);
  EXPECT_NEAR(v[9], 40, 1e-7);
  // No camera.position: the page gets the camera Systole's own framing places, as
  // `validate` reports it (clip::with_cameras_placed).
  r = run(systole() + " export " + kHeart + " -D camera=auto -o " + (dir / "auto.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  v = page_camera(dir / "auto.html");
  ASSERT_EQ(v.size(), 10u);
  r = run(systole() + " validate " + kHeart + " -D camera=auto");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(camera: frames the organs \(no position given\): at \((.*), (.*), (.*)\) m looking at \((.*), (.*), (.*)\) m)")))
      << r.output;
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(v[static_cast<std::size_t>(i)], std::stod(m[i + 1]), 1e-5) << i;
  EXPECT_GT(v[2], v[5] + 0.05) << "on +z of the organs, far enough to frame them";
}

TEST(ExportCommand, AnIrregularRhythmCannotLoopAndSaysWhy) {
  const auto dir = scratch("export_afib");
  const auto r = run(systole() + " export " + source("scenes/heart-afib.yaml") + " -o " + (dir / "a.glb").string());
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("irregular rhythm never repeats"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--encoding frames"), std::string::npos) << r.output;
  EXPECT_TRUE(listing(dir).empty());
}

TEST(ExportCommand, AFailedExportLeavesNothingBehind) {
  const auto dir = scratch("export_fails");
  // An extension no format has: refused before anything is simulated.
  auto r = run(systole() + " export " + kHeart + " -o " + (dir / "h.fbx").string());
  EXPECT_EQ(r.exit_code, 64) << r.output;
  EXPECT_NE(r.output.find(".glb, .gltf"), std::string::npos) << r.output;
  // A budget no 16 targets meet: fails after simulating, and writes nothing.
  r = run(systole() + " export " + kHeart + " --max-error 0.001% -o " + (dir / "h.glb").string());
  EXPECT_EQ(r.exit_code, 65) << r.output;
  EXPECT_NE(r.output.find("over the budget"), std::string::npos) << r.output;
  EXPECT_TRUE(listing(dir).empty()) << listing(dir).size() << " files left";
}

TEST(ExportCommand, RenderWritesTheAnimationBesideTheVideo) {
  const auto dir = scratch("render_export");
  const auto r = run(systole() + " render " + kHeart + kShort +
                     "-D output.width=64 -D output.height=48 -o " + (dir / "h.mp4").string() + " --export " +
                     (dir / "h.pc2").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "h.mp4"));
  EXPECT_TRUE(fs::exists(dir / "h.pc2"));
  EXPECT_TRUE(fs::exists(dir / "h.obj"));
}

}  // namespace
}  // namespace systole::test
