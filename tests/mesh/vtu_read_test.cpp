// ParaView series read back (mesh/vtu_read.h): what `systole export x.pvd` writes comes
// back as the recording's positions, times, regions and rest; the forms ParaView saves
// (ascii arrays, Float64 and Int64 values, UInt64 headers, polygons) are read; and every
// broken series is refused with the file and what is wrong.

#include "mesh/vtu_read.h"

#include <gtest/gtest.h>

#include <cstring>

#include "common/base64.h"
#include "common/error.h"
#include "export/recording_fixture.h"
#include "export/vtk.h"
#include "support/error_code.h"
#include "support/run.h"

namespace systole::test {
namespace {
namespace fs = std::filesystem;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "the writer's output no longer holds: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Every pose equals organ `organ`'s frames in float32 (compared as floats: the file's
/// values are float32), and the rest its rest within two float roundings.
void expect_recording(const mesh::AnimatedSurface& s, const exporter::OrganTrack& organ) {
  const auto n = static_cast<std::size_t>(organ.vertex_count());
  ASSERT_EQ(s.rest.size(), n);
  ASSERT_EQ(s.poses.size(), organ.frames_m.size());
  const auto as_float = [](double x) { return static_cast<float>(x); };
  for (std::size_t f = 0; f < s.poses.size(); ++f) {
    ASSERT_EQ(s.poses[f].size(), n);
    for (std::size_t v = 0; v < n; ++v) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(as_float(s.poses[f][v][k]), as_float(organ.frames_m[f](k, static_cast<Eigen::Index>(v))))
            << "frame " << f << ", vertex " << v;
      }
    }
  }
  // Rest = points - displacement, both float32: off by a few 1e-9 m on a 4 cm sphere,
  // against a motion of millimetres.
  for (std::size_t v = 0; v < n; ++v) {
    ASSERT_LT((s.rest[v] - organ.rest_m.col(static_cast<Eigen::Index>(v))).norm(), 1e-8) << "vertex " << v;
  }
  EXPECT_EQ(s.triangles, organ.triangles);
}

TEST(VtuRead, TheExportedSeriesComesBackAsRecorded) {
  const auto dir = scratch("vtu_read_round_trip");
  const auto rec = beating_sphere(6, false);
  exporter::write_pvd(dir / "s.pvd", rec);
  const auto s = mesh::read_vtu_series(dir / "s.pvd");
  expect_recording(s, rec.organs[0]);
  EXPECT_TRUE(s.in_seconds);
  ASSERT_EQ(s.times.size(), 6u);
  for (int f = 0; f < 6; ++f) EXPECT_NEAR(s.times[static_cast<std::size_t>(f)], f / 24.0, 1e-9) << "timestep, 9 digits";
  EXPECT_NEAR(s.duration, 6 / 24.0, 1e-9) << "the last frame spans one frame";
  EXPECT_EQ(s.parts, (std::vector<std::string>{"region_0", "region_1"}));
  EXPECT_EQ(s.vertex_part, rec.organs[0].vertex_region) << "region 0 top, 1 bottom: parts 0 and 1";
  EXPECT_EQ(s.file, (dir / "s.pvd").string());
}

TEST(VtuRead, SeveralPiecesNeedAChoice) {
  const auto dir = scratch("vtu_read_pieces");
  auto rec = beating_sphere(3, false);
  auto lung = rec.organs[0];
  lung.name = "lung";
  lung.rest_m *= 3;
  for (auto& x : lung.frames_m) x *= 3;
  rec.organs.push_back(lung);
  exporter::write_pvd(dir / "s.pvd", rec);
  const auto only = [&] { mesh::read_vtu_series(dir / "s.pvd"); };
  EXPECT_EQ(code_of(only), ExitCode::kDataError);
  const std::string m = message_of(only);
  EXPECT_NE(m.find("s_0000.vtu: holds 2 pieces (0 sphere, 1 lung)"), std::string::npos) << m;
  EXPECT_NE(m.find("choose one"), std::string::npos) << m;
  expect_recording(mesh::read_vtu_series(dir / "s.pvd", 1), rec.organs[1]);
  expect_recording(mesh::read_vtu_series(dir / "s.pvd", 0), rec.organs[0]);
  EXPECT_NE(message_of([&] { mesh::read_vtu_series(dir / "s.pvd", 2); }).find("has no piece 2"), std::string::npos);
}

/// A one-piece .vtu around `piece_body` (Points, Cells, PointData), with `root` attributes.
std::string vtu(const std::string& piece_attributes, const std::string& piece_body, const std::string& root = "") {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" " + root +
         ">\n<UnstructuredGrid>\n<Piece " + piece_attributes + ">\n" + piece_body + "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

/// A quad and a triangle over 5 points, ascii, Float64 points and Int64 cells as ParaView saves them.
std::string ascii_frame(double lift) {
  const std::string z = std::to_string(lift);
  return vtu("NumberOfPoints=\"5\" NumberOfCells=\"2\"",
             "<PointData>\n"
             "<DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">-1 3 3 -1 7</DataArray>\n"
             "</PointData>\n<Points>\n"
             "<DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n"
             "0 0 " + z + "  1 0 " + z + "\n 1 1 " + z + "  0 1 " + z + "\n 2 2 " + z + "\n</DataArray>\n"
             "</Points>\n<Cells>\n"
             "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 2 1 4</DataArray>\n"
             "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4 7</DataArray>\n"
             "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">9 5</DataArray>\n"
             "</Cells>\n",
             "byte_order=\"LittleEndian\"");
}

std::string pvd(const std::vector<std::pair<std::string, std::string>>& frames) {
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [t, f] : frames) out += "    <DataSet timestep=\"" + t + "\" part=\"0\" file=\"" + f + "\"/>\n";
  return out + "  </Collection>\n</VTKFile>\n";
}

TEST(VtuRead, AsciiArraysOfOtherTypesAndPolygonsAreRead) {
  const auto dir = scratch("vtu_read_ascii");
  fs::create_directories(dir / "frames");
  write_file(dir / "frames" / "a.vtu", ascii_frame(0));
  write_file(dir / "frames" / "b.vtu", ascii_frame(0.5));
  write_file(dir / "a.pvd", pvd({{"0.25", "frames/a.vtu"}, {"0.75", "frames/b.vtu"}}));
  const auto s = mesh::read_vtu_series(dir / "a.pvd");
  ASSERT_EQ(s.poses.size(), 2u);
  EXPECT_EQ(s.rest[4], Eigen::Vector3d(2, 2, 0)) << "no displacement: the first frame is the rest";
  EXPECT_EQ(s.poses[1][4], Eigen::Vector3d(2, 2, 0.5));
  EXPECT_EQ(s.triangles, (std::vector<Eigen::Vector3i>{{0, 1, 2}, {0, 2, 3}, {2, 1, 4}})) << "the quad fanned";
  EXPECT_EQ(s.times, (std::vector<double>{0.25, 0.75}));
  EXPECT_EQ(s.duration, 1.25);
  EXPECT_EQ(s.parts, (std::vector<std::string>{"region_3", "region_7"})) << "only the regions present";
  EXPECT_EQ(s.vertex_part, (std::vector<int>{-1, 0, 0, -1, 1}));
}

TEST(VtuRead, BinaryArraysWithUInt64HeadersAndBigEndianValuesAreRead) {
  const auto dir = scratch("vtu_read_binary_forms");
  // Three points as big-endian Float32 after a big-endian UInt64 byte count, the header
  // encoded as its own base64 stream as some VTK writers do.
  std::string header(8, '\0'), values;
  header[7] = 36;
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
    std::uint32_t b;
    std::memcpy(&b, &x, 4);
    for (int k = 3; k >= 0; --k) values += char((b >> (8 * k)) & 0xff);
  }
  write_file(dir / "t.vtu",
             vtu("NumberOfPoints=\"3\" NumberOfCells=\"1\"",
                 "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">" + base64(header) +
                     base64(values) + "</DataArray></Points>\n<Cells>\n"
                     "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>\n"
                     "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray>\n"
                     "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5</DataArray>\n</Cells>\n",
                 "byte_order=\"BigEndian\" header_type=\"UInt64\""));
  write_file(dir / "t.pvd", pvd({{"0", "t.vtu"}}));
  const auto s = mesh::read_vtu_series(dir / "t.pvd");
  ASSERT_EQ(s.poses.size(), 1u);
  EXPECT_EQ(s.poses[0], (std::vector<Eigen::Vector3d>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(s.duration, 0.0) << "a single frame spans nothing";
  EXPECT_TRUE(s.parts.empty());
}

TEST(VtuRead, AFrameOfAnotherMeshIsRefusedByItsFile) {
  const auto dir = scratch("vtu_read_other_mesh");
  const auto rec = beating_sphere(3, false);
  const auto folder = exporter::write_pvd(dir / "s.pvd", rec);
  auto other = rec;
  other.organs[0].triangles.pop_back();
  write_file(folder / "s_0002.vtu", exporter::vtu_document(other, 2));
  const auto read = [&] { mesh::read_vtu_series(dir / "s.pvd"); };
  EXPECT_EQ(code_of(read), ExitCode::kDataError);
  const std::string m = message_of(read);
  EXPECT_NE(m.find((folder / "s_0002.vtu").string() + ": frame 2 has 162 points and 319 triangles, the first frame 162 and 320"),
            std::string::npos) << m;
}

TEST(VtuRead, AMissingFrameNamesTheSeriesAndTheFrame) {
  const auto dir = scratch("vtu_read_missing_frame");
  const auto folder = exporter::write_pvd(dir / "s.pvd", beating_sphere(3, false));
  fs::remove(folder / "s_0001.vtu");
  const auto read = [&] { mesh::read_vtu_series(dir / "s.pvd"); };
  EXPECT_EQ(code_of(read), ExitCode::kNoInput);
  const std::string m = message_of(read);
  EXPECT_NE(m.find((dir / "s.pvd").string() + ": cannot read frame 1, " + (folder / "s_0001.vtu").string()), std::string::npos) << m;
  EXPECT_EQ(code_of([&] { mesh::read_vtu_series(dir / "absent.pvd"); }), ExitCode::kNoInput);
}

TEST(VtuRead, TimesMustIncreaseAndTheListMustHoldFrames) {
  const auto dir = scratch("vtu_read_times");
  exporter::write_pvd(dir / "s.pvd", beating_sphere(3, false));
  const std::string text = read_file(dir / "s.pvd");
  write_file(dir / "s.pvd", replaced(text, "timestep=\"0.0833333333\"", "timestep=\"0.01\""));
  std::string m = message_of([&] { mesh::read_vtu_series(dir / "s.pvd"); });
  EXPECT_NE(m.find("timestep 0.01 of s_frames/s_0002.vtu is not after the one before it"), std::string::npos) << m;
  write_file(dir / "s.pvd", replaced(text, "timestep=\"0\"", "timestep=\"soon\""));
  EXPECT_NE(message_of([&] { mesh::read_vtu_series(dir / "s.pvd"); }).find("'soon' is not a finite number"), std::string::npos);
  write_file(dir / "s.pvd", pvd({}));
  EXPECT_NE(message_of([&] { mesh::read_vtu_series(dir / "s.pvd"); }).find("lists no frames"), std::string::npos);
}

TEST(VtuRead, BrokenFramesAreRefusedWithWhatIsWrong) {
  const auto dir = scratch("vtu_read_broken");
  const auto folder = exporter::write_pvd(dir / "s.pvd", beating_sphere(2, false));
  const auto frame = folder / "s_0001.vtu";
  const std::string good = read_file(frame);
  const auto error_with = [&](const std::string& text) {
    write_file(frame, text);
    const auto read = [&] { mesh::read_vtu_series(dir / "s.pvd"); };
    EXPECT_EQ(code_of(read), ExitCode::kDataError);
    return message_of(read);
  };
  EXPECT_NE(error_with(good.substr(0, good.size() / 2)).find("not well-formed XML"), std::string::npos);
  std::string m = error_with(replaced(good, "NumberOfPoints=\"162\"", "NumberOfPoints=\"161\""));
  EXPECT_NE(m.find("array 'Points' holds 1944 bytes (header: 1944), expected 483 Float32 values (1932 bytes)"), std::string::npos) << m;
  m = error_with(replaced(good, "NumberOfPoints=\"162\"", "NumberOfPoints=\"2147483647\""));
  EXPECT_NE(m.find("expected 6442450941 Float32 values"), std::string::npos) << "checked before allocating: " << m;
  m = error_with(replaced(good, "format=\"binary\"", "format=\"appended\""));
  EXPECT_NE(m.find("format 'appended', which is not read"), std::string::npos) << m;
  m = error_with(replaced(good, "header_type=\"UInt32\"", "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\""));
  EXPECT_NE(m.find("compressed (vtkZLibDataCompressor)"), std::string::npos) << m;
  m = error_with(replaced(good, "type=\"UnstructuredGrid\"", "type=\"PolyData\""));
  EXPECT_NE(m.find("not a VTK UnstructuredGrid file"), std::string::npos) << m;
}

}  // namespace
}  // namespace systole::test
