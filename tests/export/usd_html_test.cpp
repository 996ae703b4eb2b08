// USD text and the web page: what no client in Debian 12 reads for us here (Debian's Blender
// has no USD; the page's playing is checked in Chromium by scripts/check-exports).

#include <gtest/gtest.h>

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
  const std::regex sample(R"(\n            (\d+): \[([^\]]*)\],)");
  int samples = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), sample); it != std::sregex_iterator(); ++it) {
    const std::string points = (*it)[2];
    EXPECT_EQ(std::count(points.begin(), points.end(), '('), rec.organs[0].vertex_count()) << "sample " << (*it)[1];
    EXPECT_EQ(std::stoi((*it)[1]), samples);
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
  const std::string page = exporter::html_page(glb, "sphere <test>");
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

}  // namespace
}  // namespace systole::test
