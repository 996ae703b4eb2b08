#include "export/vtk.h"

#include <unistd.h>

#include <bit>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/atomic_output.h"
#include "common/base64.h"
#include "common/error.h"
#include "mesh/strain.h"

namespace systole::exporter {
namespace fs = std::filesystem;

static_assert(std::endian::native == std::endian::little, "VTU arrays are declared LittleEndian and written in host order");

namespace {

/// An inline binary DataArray: base64 of the byte count (UInt32) followed by the data,
/// encoded as one stream (how VTK's own writer does it for uncompressed data).
template <class T>
void data_array(std::ostream& out, const char* type, const char* name, int components, const std::vector<T>& values) {
  std::string bytes(4 + sizeof(T) * values.size(), '\0');
  const auto count = static_cast<std::uint32_t>(sizeof(T) * values.size());
  std::memcpy(bytes.data(), &count, 4);
  if (!values.empty()) std::memcpy(bytes.data() + 4, values.data(), sizeof(T) * values.size());
  out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
      << "\" format=\"binary\">\n          " << base64(bytes) << "\n        </DataArray>\n";
}

/// The organ's name, safe inside an XML attribute.
std::string xml_text(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void piece(std::ostream& out, const OrganTrack& organ, int frame) {
  const auto& x = organ.frames_m[static_cast<std::size_t>(frame)];
  const int n = organ.vertex_count();
  const int cells = static_cast<int>(organ.triangles.size());
  out << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << cells << "\">\n";
  // Per-vertex values: what the renderer's color_by strain and activation show.
  std::vector<std::int32_t> region(static_cast<std::size_t>(n), -1);
  std::vector<float> activation(static_cast<std::size_t>(n), 0.0f), strain_f(static_cast<std::size_t>(n));
  std::vector<float> displacement(3 * static_cast<std::size_t>(n)), points(3 * static_cast<std::size_t>(n));
  const auto& phi = organ.activation[static_cast<std::size_t>(frame)];
  for (int v = 0; v < n; ++v) {
    const int r = organ.vertex_region.empty() ? -1 : organ.vertex_region[static_cast<std::size_t>(v)];
    region[static_cast<std::size_t>(v)] = r;
    if (r >= 0 && static_cast<std::size_t>(r) < phi.size()) activation[static_cast<std::size_t>(v)] = static_cast<float>(phi[static_cast<std::size_t>(r)]);
    for (int k = 0; k < 3; ++k) {
      points[3 * static_cast<std::size_t>(v) + k] = static_cast<float>(x(k, v));
      displacement[3 * static_cast<std::size_t>(v) + k] = static_cast<float>(x(k, v) - organ.rest_m(k, v));
    }
  }
  std::vector<Eigen::Vector3d> rest(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v) rest[static_cast<std::size_t>(v)] = organ.rest_m.col(v);
  std::vector<double> strain;
  mesh::VertexStrain(rest, organ.triangles).compute(x, strain);
  for (int v = 0; v < n; ++v) strain_f[static_cast<std::size_t>(v)] = static_cast<float>(strain[static_cast<std::size_t>(v)]);

  out << "      <PointData Scalars=\"strain\" Vectors=\"displacement\">\n";
  data_array(out, "Int32", "region", 1, region);
  data_array(out, "Float32", "strain", 1, strain_f);
  data_array(out, "Float32", "activation", 1, activation);
  data_array(out, "Float32", "displacement", 3, displacement);
  out << "      </PointData>\n      <Points>\n";
  data_array(out, "Float32", "Points", 3, points);
  out << "      </Points>\n      <Cells>\n";
  std::vector<std::int32_t> connectivity, offsets;
  std::vector<std::uint8_t> types(static_cast<std::size_t>(cells), 5);  // VTK_TRIANGLE
  for (int c = 0; c < cells; ++c) {
    for (int k = 0; k < 3; ++k) connectivity.push_back(organ.triangles[static_cast<std::size_t>(c)][k]);
    offsets.push_back(3 * (c + 1));
  }
  data_array(out, "Int32", "connectivity", 1, connectivity);
  data_array(out, "Int32", "offsets", 1, offsets);
  data_array(out, "UInt8", "types", 1, types);
  out << "      </Cells>\n    </Piece>\n";
}

std::string frame_name(const std::string& stem, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "_%04d.vtu", frame);
  return stem + name;
}

/// A folder being written under a temporary name, removed unless it was moved into place.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(fs::path path) : path_(std::move(path)) {
    fs::remove_all(path_);
    std::error_code ec;
    fs::create_directory(path_, ec);
    if (ec) throw Error(ExitCode::kCannotCreate, "cannot create folder '" + path_.string() + "': " + ec.message());
  }
  ~TemporaryFolder() {
    std::error_code ec;
    if (!moved_) fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  void move_to(const fs::path& target) {
    std::error_code ec;
    fs::remove_all(target, ec);
    fs::rename(path_, target, ec);
    if (ec) throw Error(ExitCode::kIoError, "cannot rename '" + path_.string() + "' to '" + target.string() + "': " + ec.message());
    moved_ = true;
  }

 private:
  fs::path path_;
  bool moved_ = false;
};

}  // namespace

std::string vtu_document(const Recording& rec, int frame) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
         "  <UnstructuredGrid>\n";
  for (const auto& organ : rec.organs) {
    out << "    <!-- " << xml_text(organ.name) << " -->\n";
    piece(out, organ, frame);
  }
  out << "  </UnstructuredGrid>\n</VTKFile>\n";
  return out.str();
}

fs::path write_pvd(const fs::path& file, const Recording& rec) {
  const std::string stem = file.stem().string();
  const fs::path folder = file.parent_path() / (stem + "_frames");
  // Take the .pvd's lock first: a second writer of the same series is refused before it
  // touches the folder.
  AtomicOutput pvd(file);
  TemporaryFolder frames(file.parent_path() /
                         ("." + stem + "_frames.partial-" + std::to_string(::getpid())));
  std::ostringstream collection;
  collection << "<?xml version=\"1.0\"?>\n"
                "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (int f = 0; f < rec.frame_count(); ++f) {
    const std::string name = frame_name(stem, f);
    write_file_atomically(frames.path() / name, vtu_document(rec, f));
    char time[32];
    std::snprintf(time, sizeof time, "%.9g", f / rec.fps);
    collection << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << xml_text(stem)
               << "_frames/" << xml_text(name) << "\"/>\n";
  }
  collection << "  </Collection>\n</VTKFile>\n";
  {
    std::ofstream out(pvd.temp_path(), std::ios::binary);
    out << collection.str();
    if (!out.flush()) throw Error(ExitCode::kIoError, "cannot write '" + file.string() + "'");
  }
  frames.move_to(folder);
  pvd.commit();
  return folder;
}

}  // namespace systole::exporter
