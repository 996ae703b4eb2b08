// PC2 and MDD: the byte layouts Blender's readers expect, read back value by value.

#include <gtest/gtest.h>

#include <bit>
#include <cstring>

#include "export/point_cache.h"
#include "recording_fixture.h"
#include "support/run.h"

namespace systole::test {
namespace {

std::uint32_t le(const std::string& b, std::size_t at) {
  const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
  return p[0] | (p[1] << 8) | (p[2] << 16) | (std::uint32_t(p[3]) << 24);
}
std::uint32_t be(const std::string& b, std::size_t at) {
  const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
  return (std::uint32_t(p[0]) << 24) | (p[1] << 16) | (p[2] << 8) | p[3];
}

TEST(PointCache, Pc2HoldsItsHeaderAndEveryFrameLittleEndian) {
  const auto dir = scratch("pc2");
  const auto rec = beating_sphere(10, false);
  const auto written = exporter::write_point_caches(dir / "s.pc2", rec);
  ASSERT_EQ(written.size(), 2u);
  const std::string b = read_file(dir / "s.pc2");
  const int n = rec.organs[0].vertex_count(), frames = rec.frame_count();
  ASSERT_EQ(b.size(), 32u + 12u * n * frames);
  EXPECT_EQ(std::memcmp(b.data(), "POINTCACHE2\0", 12), 0);
  EXPECT_EQ(le(b, 12), 1u) << "version";
  EXPECT_EQ(le(b, 16), std::uint32_t(n));
  EXPECT_EQ(std::bit_cast<float>(le(b, 20)), 0.0f) << "start frame";
  EXPECT_EQ(std::bit_cast<float>(le(b, 24)), 1.0f) << "one sample per frame";
  EXPECT_EQ(le(b, 28), std::uint32_t(frames));
  for (int f : {0, 3, frames - 1}) {
    for (int v : {0, n / 2, n - 1}) {
      for (int k = 0; k < 3; ++k) {
        const float stored = std::bit_cast<float>(le(b, 32 + 12 * (std::size_t(f) * n + v) + 4 * k));
        EXPECT_EQ(stored, static_cast<float>(rec.organs[0].frames_m[f](k, v))) << "frame " << f << " vertex " << v;
      }
    }
  }
  // The rest mesh beside it, vertices in the cache's order.
  const std::string obj = read_file(dir / "s.obj");
  EXPECT_EQ(std::count(obj.begin(), obj.end(), 'v') >= n, true);
  EXPECT_NE(obj.find("\nf 1 "), std::string::npos) << "faces are 1-based";
}

TEST(PointCache, MddIsBigEndianWithFrameTimes) {
  const auto dir = scratch("mdd");
  const auto rec = beating_sphere(6, false);
  exporter::write_point_caches(dir / "s.mdd", rec);
  const std::string b = read_file(dir / "s.mdd");
  const int n = rec.organs[0].vertex_count(), frames = rec.frame_count();
  ASSERT_EQ(b.size(), 8u + 4u * frames + 12u * n * frames);
  EXPECT_EQ(be(b, 0), std::uint32_t(frames));
  EXPECT_EQ(be(b, 4), std::uint32_t(n));
  for (int f = 0; f < frames; ++f) EXPECT_EQ(std::bit_cast<float>(be(b, 8 + 4 * f)), static_cast<float>(f / rec.fps));
  const std::size_t data = 8 + 4 * std::size_t(frames);
  for (int f : {0, frames - 1}) {
    for (int v : {0, n - 1}) {
      for (int k = 0; k < 3; ++k) {
        const float stored = std::bit_cast<float>(be(b, data + 12 * (std::size_t(f) * n + v) + 4 * k));
        EXPECT_EQ(stored, static_cast<float>(rec.organs[0].frames_m[f](k, v)));
      }
    }
  }
}

TEST(PointCache, SeveralOrgansGetACacheAndAMeshEach) {
  const auto dir = scratch("pc2_two");
  auto rec = beating_sphere(4, false);
  rec.organs.push_back(rec.organs[0]);
  rec.organs[1].name = "left lung";
  const auto written = exporter::write_point_caches(dir / "s.pc2", rec);
  ASSERT_EQ(written.size(), 4u);
  EXPECT_TRUE(std::filesystem::exists(dir / "s-sphere.pc2"));
  EXPECT_TRUE(std::filesystem::exists(dir / "s-left_lung.pc2"));
  EXPECT_TRUE(std::filesystem::exists(dir / "s-left_lung.obj"));
  EXPECT_FALSE(std::filesystem::exists(dir / "s.pc2"));
}

}  // namespace
}  // namespace systole::test
