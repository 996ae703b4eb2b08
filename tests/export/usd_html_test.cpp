// USD text and the web page: what no client in Debian 12 reads for us here (Debian's Blender
// has no USD; the page's playing is checked in Chromium by scripts/check-exports).

#include <gtest/gtest.h>

#include <cctype>
#include <regex>

#include "export/gltf.h"
#include "export/html.h"
#include "export/usd.h"
#include "recording_fixture.h"
#include "support/run.h"

namespace systole::test {
namespace {

TEST(Usd, EveryFrameIsATimeSampleOfEveryPoint) {
  const auto dir = scratch("usda");
  const auto rec = beating_sphere(4, false);
  exporter::write_usda(dir / "s.usda", rec);
  const std::string text = read_file(dir / "s.usda");
  EXPECT_EQ(text.rfind("#usda 1.0\n", 0), 0u);
  EXPECT_NE(text.find("timeCodesPerSecond = 24"), std::string::npos);
  EXPECT_NE(text.find("endTimeCode = 3"), std::string::npos);
  // Each time sample is "\n            <frame>: [<points>],". Scanned by hand: std::regex
  // recurses once per character of a sample and overflows the stack under AddressSanitizer.
  const std::string lead = "\n            ";
  int samples = 0;
  for (std::size_t at = text.find(lead); at != std::string::npos; at = text.find(lead, at + 1)) {
    const std::size_t first = at + lead.size();
    std::size_t end = first;
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
    if (end == first || text.compare(end, 3, ": [") != 0) continue;
    const std::size_t close = text.find("],", end + 3);
    ASSERT_NE(close, std::string::npos);
    const std::string frame = text.substr(first, end - first), points = text.substr(end + 3, close - end - 3);
    EXPECT_EQ(points.find(']'), std::string::npos) << "sample " << frame;
    EXPECT_EQ(std::count(points.begin(), points.end(), '('), rec.organs[0].vertex_count()) << "sample " << frame;
    EXPECT_EQ(std::stoi(frame), samples);
    ++samples;
  }
  EXPECT_EQ(samples, rec.frame_count());
  // Brackets and braces balance: the layer parses as nested lists and blocks.
  EXPECT_EQ(std::count(text.begin(), text.end(), '['), std::count(text.begin(), text.end(), ']'));
  EXPECT_EQ(std::count(text.begin(), text.end(), '{'), std::count(text.begin(), text.end(), '}'));
}

TEST(Html, ThePageCarriesItsModelAndScriptsAndFetchesNothing) {
  const auto rec = beating_sphere();
  const std::string glb = exporter::gltf_bytes(rec, {exporter::compact_morph(rec.organs[0], rec, {})}, true);
  const std::string page = exporter::html_page(glb, "sphere <test>", scene::Camera{});
  EXPECT_NE(page.find("<title>sphere &lt;test&gt;</title>"), std::string::npos);
  for (const char* name : {"\"three\": \"data:text/javascript;base64,", "\"three/addons/loaders/GLTFLoader.js\": \"data:",
                           "\"three/addons/controls/OrbitControls.js\": \"data:",
                           "\"three/addons/utils/BufferGeometryUtils.js\": \"data:"}) {
    EXPECT_NE(page.find(name), std::string::npos) << name;
  }
  EXPECT_EQ(page.find("<script src"), std::string::npos) << "no script from elsewhere";
  EXPECT_EQ(page.find("<link"), std::string::npos) << "no stylesheet from elsewhere";
  // The model is the GLB, base64 in the page.
  const auto start = page.find("<script id=\"model\" type=\"application/octet-stream\">\n");
  ASSERT_NE(start, std::string::npos);
  const auto body = start + std::string("<script id=\"model\" type=\"application/octet-stream\">\n").size();
  const std::string encoded = page.substr(body, page.find('\n', body) - body);
  EXPECT_EQ(encoded.size(), (glb.size() + 2) / 3 * 4);
  EXPECT_EQ(encoded.substr(0, 8), "Z2xURgIA") << "base64 of 'glTF' and version 2";
}

/// The numbers of the page's embedded camera: {"position": [3], "target": [3], "up": [3], "fov_deg"}.
std::vector<double> page_camera(const std::string& page) {
  const std::regex json(
      R"re(<script id="camera" type="application/json">\{"position": \[(.*), (.*), (.*)\], "target": \[(.*), (.*), (.*)\], "up": \[(.*), (.*), (.*)\], "fov_deg": (.*)\}</script>)re");
  std::smatch m;
  if (!std::regex_search(page, m, json)) return {};
  std::vector<double> v;
  for (std::size_t i = 1; i < m.size(); ++i) v.push_back(std::stod(m[i]));
  return v;
}

TEST(Html, ThePageOpensOnTheScenesCameraWithTheRenderersUp) {
  const auto rec = beating_sphere();
  const std::string glb = exporter::gltf_bytes(rec, {exporter::compact_morph(rec.organs[0], rec, {})}, true);
  scene::Camera camera;
  camera.position_m = Eigen::Vector3d(0.1, 0.2, 0.3);
  camera.target_m = Eigen::Vector3d(0.01, -0.02, 0.03);
  camera.up = Eigen::Vector3d(0, 2, 0.5);  // Neither unit nor perpendicular to the view.
  camera.fov_rad = 35 * M_PI / 180;
  const auto v = page_camera(exporter::html_page(glb, "sphere", camera));
  ASSERT_EQ(v.size(), 10u);
  const Eigen::Vector3d position(v[0], v[1], v[2]), target(v[3], v[4], v[5]), up(v[6], v[7], v[8]);
  EXPECT_LT((position - camera.position_m).norm(), 1e-9);
  EXPECT_LT((target - camera.target_m).norm(), 1e-9);
  EXPECT_NEAR(v[9], 35, 1e-7);
  // The renderer's up: unit, perpendicular to the view, on the side of the given one.
  EXPECT_NEAR(up.norm(), 1, 1e-8);
  EXPECT_NEAR(up.dot((target - position).normalized()), 0, 1e-8);
  EXPECT_GT(up.dot(camera.up), 0);
  // An up along the view direction is replaced by a perpendicular one, as render::look_at does.
  camera.up = camera.target_m - camera.position_m;
  const auto w = page_camera(exporter::html_page(glb, "sphere", camera));
  ASSERT_EQ(w.size(), 10u);
  EXPECT_NEAR(Eigen::Vector3d(w[6], w[7], w[8]).dot(camera.up.normalized()), 0, 1e-8);
  EXPECT_NEAR(Eigen::Vector3d(w[6], w[7], w[8]).norm(), 1, 1e-8);
}

}  // namespace
}  // namespace systole::test
