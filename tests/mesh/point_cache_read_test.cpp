// Point caches read back (mesh/point_cache_read.h): what `systole export` writes (PC2, MDD
// and the OBJ beside them) comes back as the recording's positions, times and rest mesh;
// the OBJ forms other programs write are read as written; and every broken file is refused
// with its path and what is wrong.

#include "mesh/point_cache_read.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "common/error.h"
#include "export/point_cache.h"
#include "export/recording_fixture.h"
#include "support/error_code.h"
#include "support/run.h"

namespace systole::test {
namespace {
namespace fs = std::filesystem;

/// Every pose equals the recording's frames in float32, and the rest its rest mesh: the
/// OBJ's nine digits are read as the decimal they say, which rounds to the float written.
/// Compared as floats: a value read from a float32 file is one, so nothing is lost.
void expect_recording(const mesh::AnimatedSurface& s, const exporter::OrganTrack& organ) {
  const auto n = static_cast<std::size_t>(organ.vertex_count());
  ASSERT_EQ(s.rest.size(), n);
  ASSERT_EQ(s.poses.size(), organ.frames_m.size());
  const auto as_float = [](double x) { return static_cast<float>(x); };
  for (std::size_t v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(as_float(s.rest[v][k]), as_float(organ.rest_m(k, static_cast<Eigen::Index>(v)))) << "vertex " << v;
    }
  }
  for (std::size_t f = 0; f < s.poses.size(); ++f) {
    ASSERT_EQ(s.poses[f].size(), n);
    for (std::size_t v = 0; v < n; ++v) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(as_float(s.poses[f][v][k]), as_float(organ.frames_m[f](k, static_cast<Eigen::Index>(v))))
            << "frame " << f << ", vertex " << v;
      }
    }
  }
  EXPECT_EQ(s.triangles, organ.triangles);
  EXPECT_EQ(s.parts, std::vector<std::string>{organ.name}) << "the OBJ's `o` line";
  EXPECT_EQ(s.vertex_part, std::vector<int>(n, 0));
}

/// Overwrites 4 bytes of `file` at `at` (a header field or a coordinate).
void patch(const fs::path& file, std::size_t at, const char bytes[4]) {
  std::string b = read_file(file);
  std::memcpy(b.data() + at, bytes, 4);
  write_file(file, b);
}

void patch_le32(const fs::path& file, std::size_t at, std::uint32_t v) {
  const char b[4] = {char(v & 0xff), char((v >> 8) & 0xff), char((v >> 16) & 0xff), char(v >> 24)};
  patch(file, at, b);
}

void patch_be32(const fs::path& file, std::size_t at, std::uint32_t v) {
  const char b[4] = {char(v >> 24), char((v >> 16) & 0xff), char((v >> 8) & 0xff), char(v & 0xff)};
  patch(file, at, b);
}

std::uint32_t bits(float f) {
  std::uint32_t b;
  std::memcpy(&b, &f, 4);
  return b;
}

/// A PC2 of `points` points, `samples` samples, each coordinate its own index.
std::string pc2_bytes(int points, int samples, float start = 0, float rate = 1) {
  std::string b("POINTCACHE2\0", 12);
  auto put = [&](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) b += char((v >> (8 * k)) & 0xff);
  };
  put(1);
  put(static_cast<std::uint32_t>(points));
  put(bits(start));
  put(bits(rate));
  put(static_cast<std::uint32_t>(samples));
  for (int i = 0; i < 3 * points * samples; ++i) put(bits(static_cast<float>(i)));
  return b;
}

TEST(PointCacheRead, Pc2ComesBackAsRecordedInFrames) {
  const auto dir = scratch("point_cache_read_pc2");
  const auto rec = beating_sphere(12, false);
  exporter::write_point_caches(dir / "s.pc2", rec);
  const auto s = mesh::read_point_cache(dir / "s.pc2");
  expect_recording(s, rec.organs[0]);
  EXPECT_FALSE(s.in_seconds) << "PC2 counts frames";
  std::vector<double> frames;
  for (int f = 0; f < 12; ++f) frames.push_back(f);
  EXPECT_EQ(s.times, frames);
  EXPECT_EQ(s.duration, 12.0);
  EXPECT_EQ(s.file, (dir / "s.pc2").string());
}

TEST(PointCacheRead, MddComesBackAsRecordedInSeconds) {
  const auto dir = scratch("point_cache_read_mdd");
  const auto rec = beating_sphere(10, false);
  exporter::write_point_caches(dir / "s.mdd", rec);
  const auto s = mesh::read_point_cache(dir / "s.mdd");
  expect_recording(s, rec.organs[0]);
  EXPECT_TRUE(s.in_seconds);
  ASSERT_EQ(s.times.size(), 10u);
  for (int f = 0; f < 10; ++f) EXPECT_EQ(s.times[static_cast<std::size_t>(f)], double(float(f / rec.fps))) << f;
  // The last frame spans one frame: ten frames at 24 fps last 10/24 s (float32 times).
  EXPECT_NEAR(s.duration, 10 / rec.fps, 1e-6);
}

TEST(PointCacheRead, EachOrganOfSeveralHasItsOwnCacheAndObj) {
  const auto dir = scratch("point_cache_read_organs");
  auto rec = beating_sphere(6, false);
  auto second = rec.organs[0];
  second.name = "left lung";
  for (auto& x : second.frames_m) x *= 2;
  second.rest_m *= 2;
  rec.organs.push_back(second);
  exporter::write_point_caches(dir / "clip.pc2", rec);
  // export/recording.h's organ_file: `<stem>-<organ>` with the organ's space as '_'.
  const auto s = mesh::read_point_cache(dir / "clip-left_lung.pc2");
  expect_recording(s, rec.organs[1]);
}

TEST(PointCacheRead, ARestMeshElsewhereIsGivenByPath) {
  const auto dir = scratch("point_cache_read_override");
  const auto rec = beating_sphere(4, false);
  exporter::write_point_caches(dir / "s.mdd", rec);
  fs::create_directory(dir / "meshes");
  fs::rename(dir / "s.obj", dir / "meshes" / "rest.obj");
  const auto s = mesh::read_point_cache(dir / "s.mdd", dir / "meshes" / "rest.obj");
  expect_recording(s, rec.organs[0]);
}

TEST(PointCacheRead, TheObjIsReadAsWrittenWithItsFaceFormsAndParts) {
  const auto dir = scratch("point_cache_read_obj_forms");
  write_file(dir / "m.obj",
             "# a quad in one object, a triangle in a group, one vertex unused\n"
             "mtllib m.mtl\n"
             "o first\n"
             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
             "vt 0 0\nvn 0 0 1\n"
             "s off\n"
             "f 1/1/1 2/1/1 3/1/1 4/1/1\n"
             "g second part\n"
             "v 0 0 1 0.5 0.5 0.5\n"
             "f -1//1 -4//1 -3/1\r\n"
             "v 5 5 5\n");
  write_file(dir / "m.pc2", pc2_bytes(6, 2, 10, 0.5f));
  const auto s = mesh::read_point_cache(dir / "m.pc2");
  ASSERT_EQ(s.rest.size(), 6u);
  EXPECT_EQ(s.rest[4], Eigen::Vector3d(0, 0, 1)) << "a colour after x y z is ignored";
  EXPECT_EQ(s.triangles, (std::vector<Eigen::Vector3i>{{0, 1, 2}, {0, 2, 3}, {4, 1, 2}}))
      << "the quad fanned from its first corner; negative indices count back from the last `v`";
  EXPECT_EQ(s.parts, (std::vector<std::string>{"first", "second part"}));
  EXPECT_EQ(s.vertex_part, (std::vector<int>{0, 0, 0, 0, 1, -1})) << "shared vertices stay in the first part";
  EXPECT_EQ(s.times, (std::vector<double>{10, 10.5})) << "start + k x sample rate";
  EXPECT_EQ(s.duration, 1.0) << "2 samples x 0.5 frames";
  ASSERT_EQ(s.poses.size(), 2u);
  EXPECT_EQ(s.poses[1][5], Eigen::Vector3d(33, 34, 35)) << "sample 1, point 5: the 12th point written";
}

TEST(PointCacheRead, AnObjWithoutNamesHasNoParts) {
  const auto dir = scratch("point_cache_read_no_parts");
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write_file(dir / "m.pc2", pc2_bytes(3, 1));
  const auto s = mesh::read_point_cache(dir / "m.pc2");
  EXPECT_TRUE(s.parts.empty());
  EXPECT_TRUE(s.vertex_part.empty());
  EXPECT_EQ(s.duration, 1.0);
}

TEST(PointCacheRead, AMissingObjNamesTheCacheAndTheObj) {
  const auto dir = scratch("point_cache_read_missing_obj");
  exporter::write_point_caches(dir / "s.pc2", beating_sphere(3, false));
  fs::remove(dir / "s.obj");
  const auto read = [&] { mesh::read_point_cache(dir / "s.pc2"); };
  EXPECT_EQ(code_of(read), ExitCode::kNoInput);
  const std::string m = message_of(read);
  EXPECT_NE(m.find((dir / "s.pc2").string()), std::string::npos) << m;
  EXPECT_NE(m.find((dir / "s.obj").string()), std::string::npos) << m;
  EXPECT_NE(m.find("not found"), std::string::npos) << m;
  EXPECT_EQ(code_of([&] { mesh::read_point_cache(dir / "absent.mdd"); }), ExitCode::kNoInput);
}

TEST(PointCacheRead, APointCountOtherThanTheObjsIsRefused) {
  const auto dir = scratch("point_cache_read_count");
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
  write_file(dir / "m.pc2", pc2_bytes(3, 2));
  const auto read = [&] { mesh::read_point_cache(dir / "m.pc2"); };
  EXPECT_EQ(code_of(read), ExitCode::kDataError);
  const std::string m = message_of(read);
  EXPECT_NE(m.find("3 points per frame"), std::string::npos) << m;
  EXPECT_NE(m.find("has 4 vertices"), std::string::npos) << m;
}

TEST(PointCacheRead, ACacheCutShortOrLongerThanItsHeaderIsRefused) {
  const auto dir = scratch("point_cache_read_truncated");
  const auto rec = beating_sphere(5, false);
  for (const char* name : {"s.pc2", "s.mdd"}) {
    exporter::write_point_caches(dir / name, rec);
    const std::string whole = read_file(dir / name);
    write_file(dir / name, whole.substr(0, whole.size() - 7));
    const std::string m = message_of([&] { mesh::read_point_cache(dir / name); });
    EXPECT_NE(m.find("cut short"), std::string::npos) << name << ": " << m;
    write_file(dir / name, whole + "tail");
    EXPECT_NE(message_of([&] { mesh::read_point_cache(dir / name); }).find("does not describe the data"), std::string::npos) << name;
  }
}

TEST(PointCacheRead, AHeaderClaimingBillionsOfPointsIsRefusedBeforeAllocating) {
  const auto dir = scratch("point_cache_read_huge_header");
  exporter::write_point_caches(dir / "s.pc2", beating_sphere(3, false));
  exporter::write_point_caches(dir / "s.mdd", beating_sphere(3, false));
  patch_le32(dir / "s.pc2", 16, 0x7fffffff);  // points
  patch_le32(dir / "s.pc2", 28, 0x7fffffff);  // samples
  patch_be32(dir / "s.mdd", 0, 0x7fffffff);   // frames
  patch_be32(dir / "s.mdd", 4, 0x7fffffff);   // points
  // 2^31 x 2^31 positions would be 55 EB: only the size check stands between them and new.
  for (const char* name : {"s.pc2", "s.mdd"}) {
    const std::string m = message_of([&] { mesh::read_point_cache(dir / name); });
    EXPECT_NE(m.find("2147483647 points x 2147483647"), std::string::npos) << name << ": " << m;
    EXPECT_NE(m.find("cut short"), std::string::npos) << name << ": " << m;
  }
}

TEST(PointCacheRead, NoSamplesOrNonFiniteCoordinatesAreRefused) {
  const auto dir = scratch("point_cache_read_bad_values");
  const auto rec = beating_sphere(3, false);
  exporter::write_point_caches(dir / "s.pc2", rec);
  exporter::write_point_caches(dir / "s.mdd", rec);
  const std::string pc2 = read_file(dir / "s.pc2"), mdd = read_file(dir / "s.mdd");

  patch_le32(dir / "s.pc2", 28, 0);
  EXPECT_NE(message_of([&] { mesh::read_point_cache(dir / "s.pc2"); }).find("no samples"), std::string::npos);
  patch_be32(dir / "s.mdd", 0, 0);
  EXPECT_NE(message_of([&] { mesh::read_point_cache(dir / "s.mdd"); }).find("no frames"), std::string::npos);

  const std::size_t n = static_cast<std::size_t>(rec.organs[0].vertex_count());
  write_file(dir / "s.pc2", pc2);
  patch_le32(dir / "s.pc2", 32 + 12 * n + 4, bits(std::numeric_limits<float>::quiet_NaN()));  // sample 1, point 0, y
  std::string m = message_of([&] { mesh::read_point_cache(dir / "s.pc2"); });
  EXPECT_NE(m.find("sample 1, point 0 has a non-finite coordinate"), std::string::npos) << m;
  write_file(dir / "s.mdd", mdd);
  patch_be32(dir / "s.mdd", 8 + 4 * 3 + 12 * 2, bits(std::numeric_limits<float>::infinity()));  // frame 0, point 2, x
  m = message_of([&] { mesh::read_point_cache(dir / "s.mdd"); });
  EXPECT_NE(m.find("frame 0, point 2 has a non-finite coordinate"), std::string::npos) << m;
}

TEST(PointCacheRead, MddTimesMustIncrease) {
  const auto dir = scratch("point_cache_read_mdd_times");
  exporter::write_point_caches(dir / "s.mdd", beating_sphere(3, false));
  patch_be32(dir / "s.mdd", 8 + 4 * 2, bits(0.01f));  // frame 2 before frame 1 (1/24 s)
  const auto read = [&] { mesh::read_point_cache(dir / "s.mdd"); };
  EXPECT_EQ(code_of(read), ExitCode::kDataError);
  EXPECT_NE(message_of(read).find("frame 2's time"), std::string::npos) << message_of(read);
}

TEST(PointCacheRead, WrongSignaturesExtensionsAndObjLinesAreRefusedWithWhere) {
  const auto dir = scratch("point_cache_read_bad_files");
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write_file(dir / "m.pc2", "POINTCACHE3" + pc2_bytes(3, 1).substr(11));
  EXPECT_NE(message_of([&] { mesh::read_point_cache(dir / "m.pc2"); }).find("signature POINTCACHE2"), std::string::npos);
  EXPECT_EQ(code_of([&] { mesh::read_point_cache(dir / "m.obj"); }), ExitCode::kDataError) << "not a cache's extension";

  write_file(dir / "m.pc2", pc2_bytes(3, 1));
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  std::string m = message_of([&] { mesh::read_point_cache(dir / "m.pc2"); });
  EXPECT_NE(m.find((dir / "m.obj").string() + ":4: face corner 4 is out of range"), std::string::npos) << m;
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 zero\n");
  m = message_of([&] { mesh::read_point_cache(dir / "m.pc2"); });
  EXPECT_NE(m.find(":2: 'zero' is not a number"), std::string::npos) << m;
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
  m = message_of([&] { mesh::read_point_cache(dir / "m.pc2"); });
  EXPECT_NE(m.find(":4: a face needs at least 3 corners"), std::string::npos) << m;
}

}  // namespace
}  // namespace systole::test
