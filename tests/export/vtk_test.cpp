// ParaView's series: a .pvd listing every frame, each VTU well formed with the right counts
// and its arrays' byte counts matching what they hold.

#include <gtest/gtest.h>

#include <regex>

#include "common/base64.h"
#include "export/vtk.h"
#include "recording_fixture.h"
#include "support/run.h"

namespace systole::test {
namespace {

/// Every opened tag closed in order (the XML here has no text that holds '<').
bool balanced(const std::string& xml) {
  std::vector<std::string> open;
  std::regex tag(R"(<(/?)([A-Za-z]+)[^>]*?(/?)>)");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), tag); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    if (m[3] == "/") continue;
    if (m[1] == "/") {
      if (open.empty() || open.back() != m[2]) return false;
      open.pop_back();
    } else {
      open.push_back(m[2]);
    }
  }
  return open.empty();
}

TEST(Vtk, APieceHasItsCountsAndEveryArrayItsBytes) {
  const auto rec = beating_sphere(3, false);
  const std::string vtu = exporter::vtu_document(rec, 1);
  EXPECT_TRUE(balanced(vtu));
  EXPECT_FALSE(balanced(vtu.substr(0, vtu.size() - 12))) << "the balance check can fail";
  const int n = rec.organs[0].vertex_count();
  const int cells = static_cast<int>(rec.organs[0].triangles.size());
  EXPECT_NE(vtu.find("NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(cells) + "\""),
            std::string::npos);
  const std::map<std::string, std::size_t> expected = {
      {"region", 4u * n},         {"strain", 4u * n},           {"activation", 4u * n},
      {"displacement", 12u * n},  {"Points", 12u * n},          {"connectivity", 12u * cells},
      {"offsets", 4u * cells},    {"types", std::size_t(cells)}};
  std::regex array(R"re(<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d)" format="binary">\s*([A-Za-z0-9+/=]+)\s*</DataArray>)re");
  std::size_t found = 0;
  for (auto it = std::sregex_iterator(vtu.begin(), vtu.end(), array); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[2];
    const std::string bytes = base64_decode((*it)[4].str()).value_or("");
    ASSERT_GE(bytes.size(), 4u);
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data(), 4);
    ASSERT_TRUE(expected.count(name)) << name;
    EXPECT_EQ(count, expected.at(name)) << name;
    EXPECT_EQ(bytes.size(), 4 + count) << name;
    ++found;
    if (name == "Points") {
      float x0 = 0;
      std::memcpy(&x0, bytes.data() + 4, 4);
      EXPECT_EQ(x0, static_cast<float>(rec.organs[0].frames_m[1](0, 0))) << "frame 1's first point";
    }
  }
  EXPECT_EQ(found, expected.size());
}

TEST(Vtk, TheSeriesListsEveryFrameAndItsFilesExist) {
  const auto dir = scratch("pvd");
  const auto rec = beating_sphere(5, false);
  const auto folder = exporter::write_pvd(dir / "s.pvd", rec);
  const std::string pvd = read_file(dir / "s.pvd");
  EXPECT_TRUE(balanced(pvd));
  std::regex dataset("<DataSet timestep=\"([^\"]+)\"[^>]*file=\"([^\"]+)\"");
  int frames = 0;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset); it != std::sregex_iterator(); ++it) {
    EXPECT_TRUE(std::filesystem::exists(dir / (*it)[2].str())) << (*it)[2];
    EXPECT_NEAR(std::stod((*it)[1]), frames / rec.fps, 1e-8) << "nine significant digits";
    ++frames;
  }
  EXPECT_EQ(frames, 5);
  EXPECT_EQ(folder, dir / "s_frames");
  // Nothing temporary left beside them.
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << e.path();
  }
}

}  // namespace
}  // namespace systole::test
