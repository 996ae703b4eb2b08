#include "mesh/vtu_read.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include "common/base64.h"
#include "common/error.h"
#include "common/input_file.h"

namespace systole::mesh {
namespace fs = std::filesystem;
using tinyxml2::XMLElement;
namespace {

[[noreturn]] void data_error(const fs::path& file, const std::string& what) {
  throw Error(ExitCode::kDataError, file.string() + ": " + what);
}

/// A parsed XML file whose root is <VTKFile type="`type`">.
std::unique_ptr<tinyxml2::XMLDocument> load(const fs::path& file, const char* type, const std::string& listed_by) {
  if (const auto reason = unreadable_file_reason(file)) {
    throw Error(ExitCode::kNoInput, (listed_by.empty() ? "" : listed_by + ": ") + "cannot read " + file.string() +
                                        ": it is " + *reason);
  }
  auto doc = std::make_unique<tinyxml2::XMLDocument>();
  if (doc->LoadFile(file.c_str()) != tinyxml2::XML_SUCCESS) {
    data_error(file, "not well-formed XML (line " + std::to_string(doc->ErrorLineNum()) + ": " + doc->ErrorStr() + ")");
  }
  const XMLElement* root = doc->RootElement();
  const char* found = root != nullptr ? root->Attribute("type") : nullptr;
  if (root == nullptr || std::strcmp(root->Name(), "VTKFile") != 0 || found == nullptr || std::strcmp(found, type) != 0) {
    data_error(file, std::string("not a VTK ") + type + " file: expected <VTKFile type=\"" + type + "\">");
  }
  return doc;
}

/// The child element `name` of `parent`, which must have it.
const XMLElement* child(const XMLElement* parent, const char* name, const fs::path& file) {
  const XMLElement* e = parent->FirstChildElement(name);
  if (e == nullptr) data_error(file, std::string("<") + parent->Name() + "> has no <" + name + ">");
  return e;
}

// ---------------------------------------------------------------------------------------
// The .pvd: each frame's time and file.

struct Frame {
  double time_s = 0;
  fs::path file;
};

std::vector<Frame> read_collection(const fs::path& pvd) {
  const auto doc = load(pvd, "Collection", "");
  std::vector<Frame> frames;
  for (const XMLElement* d = child(doc->RootElement(), "Collection", pvd)->FirstChildElement("DataSet"); d != nullptr;
       d = d->NextSiblingElement("DataSet")) {
    const char* time = d->Attribute("timestep");
    const char* file = d->Attribute("file");
    if (time == nullptr || file == nullptr) data_error(pvd, "a <DataSet> needs both timestep and file");
    char* end = nullptr;
    const double t = std::strtod(time, &end);
    if (end == time || *end != '\0' || !std::isfinite(t)) data_error(pvd, std::string("timestep '") + time + "' is not a finite number");
    if (!frames.empty() && t <= frames.back().time_s) {
      data_error(pvd, "timestep " + std::string(time) + " of " + file + " is not after the one before it (" +
                          std::to_string(frames.back().time_s) + "); expected increasing times, one DataSet per frame");
    }
    const fs::path path(file);
    frames.push_back({t, path.is_absolute() ? path : pvd.parent_path() / path});
  }
  if (frames.empty()) data_error(pvd, "the collection lists no frames (no <DataSet> in <Collection>)");
  return frames;
}

// ---------------------------------------------------------------------------------------
// DataArrays: binary (base64) or ascii, any numeric type, as doubles.

/// How a .vtu's binary arrays are laid out (its <VTKFile> attributes).
struct Layout {
  bool big_endian = false;
  std::size_t header_bytes = 4;  // UInt32 or UInt64 byte count before each array's values
};

Layout layout_of(const XMLElement* root, const fs::path& file) {
  Layout l;
  if (const char* c = root->Attribute("compressor"); c != nullptr && *c != '\0') {
    data_error(file, std::string("its arrays are compressed (") + c + "), which is not read; save it uncompressed");
  }
  if (const char* order = root->Attribute("byte_order")) l.big_endian = std::strcmp(order, "BigEndian") == 0;
  if (const char* h = root->Attribute("header_type")) {
    if (std::strcmp(h, "UInt64") == 0) l.header_bytes = 8;
    else if (std::strcmp(h, "UInt32") != 0) data_error(file, std::string("header_type ") + h + "; expected UInt32 or UInt64");
  }
  return l;
}

/// The byte size of VTK type `type`, 0 if unknown.
std::size_t type_size(const std::string& type) {
  static const std::map<std::string, std::size_t> sizes = {
      {"Int8", 1},  {"UInt8", 1},  {"Int16", 2},  {"UInt16", 2},  {"Int32", 4},   {"UInt32", 4},
      {"Int64", 8}, {"UInt64", 8}, {"Float32", 4}, {"Float64", 8}, {"Char", 1}, {"UChar", 1}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

/// `size` bytes at `p` as an unsigned number, in the file's byte order.
std::uint64_t unsigned_at(const char* p, std::size_t size, bool big_endian) {
  unsigned char b[8];
  std::memcpy(b, p, size);
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < size; ++i) v |= std::uint64_t(b[big_endian ? size - 1 - i : i]) << (8 * i);
  return v;
}

/// One value of VTK type `type` (of `size` bytes) from its bits.
double value_of(std::uint64_t bits, const std::string& type, std::size_t size) {
  if (type == "Float32") {
    const auto b = static_cast<std::uint32_t>(bits);
    float f;
    std::memcpy(&f, &b, 4);
    return f;
  }
  if (type == "Float64") {
    double d;
    std::memcpy(&d, &bits, 8);
    return d;
  }
  const bool is_signed = type[0] == 'I' || type == "Char";
  if (is_signed && size < 8 && (bits >> (8 * size - 1)) != 0) bits |= ~std::uint64_t(0) << (8 * size);  // sign-extend
  return is_signed ? static_cast<double>(static_cast<std::int64_t>(bits)) : static_cast<double>(bits);
}

/// What names an array in messages: "file: array 'Points'".
std::string array_where(const fs::path& file, const std::string& name) { return file.string() + ": array '" + name + "'"; }

std::vector<double> binary_values(const char* text, const std::string& type, std::size_t count, const Layout& layout,
                                  const fs::path& file, const std::string& name) {
  const auto bytes = base64_decode(text != nullptr ? text : "");
  if (!bytes) throw Error(ExitCode::kDataError, array_where(file, name) + " is not valid base64");
  const std::size_t size = type_size(type);
  if (bytes->size() < layout.header_bytes) throw Error(ExitCode::kDataError, array_where(file, name) + " has no byte-count header");
  const std::uint64_t declared = unsigned_at(bytes->data(), layout.header_bytes, layout.big_endian);
  const std::size_t held = bytes->size() - layout.header_bytes;
  // The piece's counts say how many values there must be; they are checked against the
  // bytes actually present before any vector is sized by them.
  if (held / size < count || declared != count * size) {
    throw Error(ExitCode::kDataError, array_where(file, name) + " holds " + std::to_string(held) + " bytes (header: " +
                                          std::to_string(declared) + "), expected " + std::to_string(count) + " " +
                                          type + " values (" + std::to_string(count * size) + " bytes)");
  }
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    out[i] = value_of(unsigned_at(bytes->data() + layout.header_bytes + i * size, size, layout.big_endian), type, size);
  }
  return out;
}

std::vector<double> ascii_values(const char* text, std::size_t count, const fs::path& file, const std::string& name) {
  std::vector<double> out;
  const char* p = text != nullptr ? text : "";
  while (true) {
    while (*p != '\0' && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (*p == '\0') break;
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p) throw Error(ExitCode::kDataError, array_where(file, name) + ": '" + std::string(p, std::min<std::size_t>(std::strlen(p), 16)) + "' is not a number");
    if (out.size() == count) break;  // one too many: reported below
    out.push_back(v);
    p = end;
  }
  if (out.size() != count || *p != '\0') {
    throw Error(ExitCode::kDataError, array_where(file, name) + " holds " + (out.size() == count ? "more than " : "") +
                                          std::to_string(out.size()) + " values, expected " + std::to_string(count));
  }
  return out;
}

/// The values of `array`, which must hold `tuples` x `components` numbers.
std::vector<double> array_values(const XMLElement* array, std::size_t tuples, int components, const Layout& layout,
                                 const fs::path& file) {
  const std::string name = array->Attribute("Name") != nullptr ? array->Attribute("Name") : "(unnamed)";
  const std::string type = array->Attribute("type") != nullptr ? array->Attribute("type") : "";
  if (type_size(type) == 0) throw Error(ExitCode::kDataError, array_where(file, name) + " has type '" + type + "'; expected one of VTK's numeric types");
  const int given = array->IntAttribute("NumberOfComponents", 1);
  if (given != components) {
    throw Error(ExitCode::kDataError, array_where(file, name) + " has " + std::to_string(given) + " components, expected " + std::to_string(components));
  }
  const std::string format = array->Attribute("format") != nullptr ? array->Attribute("format") : "";
  const std::size_t count = tuples * static_cast<std::size_t>(components);
  if (format == "binary") return binary_values(array->GetText(), type, count, layout, file, name);
  if (format == "ascii") return ascii_values(array->GetText(), count, file, name);
  throw Error(ExitCode::kDataError, array_where(file, name) + " has format '" + format +
                                        "', which is not read; expected binary (inline) or ascii: save from ParaView with "
                                        "Data Mode Binary or Ascii, not Appended");
}

/// The DataArray named `name` under `parent`, or null.
const XMLElement* find_array(const XMLElement* parent, const char* name) {
  if (parent == nullptr) return nullptr;
  for (const XMLElement* a = parent->FirstChildElement("DataArray"); a != nullptr; a = a->NextSiblingElement("DataArray")) {
    const char* n = a->Attribute("Name");
    if (n != nullptr && std::strcmp(n, name) == 0) return a;
  }
  return nullptr;
}

const XMLElement* required_array(const XMLElement* parent, const char* name, const fs::path& file) {
  const XMLElement* a = find_array(parent, name);
  if (a == nullptr) data_error(file, std::string("the piece has no array '") + name + "' in <" + parent->Name() + ">");
  return a;
}

// ---------------------------------------------------------------------------------------
// One frame: a piece's points, cells and per-point arrays.

struct Piece {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3i> triangles;
  std::vector<Eigen::Vector3d> displacement;  ///< Empty without the array.
  std::vector<int> region;                    ///< Empty without the array.
};

/// The name a writer put in a comment just before a piece (export/vtk.cpp does), or "".
std::string comment_before(const XMLElement* piece) {
  const tinyxml2::XMLNode* n = piece->PreviousSibling();
  if (n == nullptr || n->ToComment() == nullptr) return {};
  std::string text = n->Value();
  const auto begin = text.find_first_not_of(" \t\n");
  const auto end = text.find_last_not_of(" \t\n");
  return begin == std::string::npos ? std::string() : text.substr(begin, end - begin + 1);
}

/// The piece the caller asked for, or an error saying which there are.
const XMLElement* choose_piece(const XMLElement* grid, int piece, const fs::path& file) {
  std::vector<const XMLElement*> pieces;
  for (const XMLElement* p = grid->FirstChildElement("Piece"); p != nullptr; p = p->NextSiblingElement("Piece")) pieces.push_back(p);
  if (pieces.empty()) data_error(file, "<UnstructuredGrid> holds no <Piece>");
  if (piece == -1 && pieces.size() == 1) return pieces[0];
  if (piece >= 0 && static_cast<std::size_t>(piece) < pieces.size()) return pieces[static_cast<std::size_t>(piece)];
  std::string list;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const std::string name = comment_before(pieces[i]);
    list += (i > 0 ? ", " : "") + std::to_string(i) + (name.empty() ? "" : " " + name);
  }
  const std::string count = std::to_string(pieces.size()) + " pieces (" + list + ")";
  if (piece == -1) data_error(file, "holds " + count + ", one per organ: choose one by its index, 0 to " + std::to_string(pieces.size() - 1));
  data_error(file, "has no piece " + std::to_string(piece) + ": it holds " + count);
}

/// The piece's cells as triangles: triangles as they are, quads and polygons fanned.
std::vector<Eigen::Vector3i> read_cells(const XMLElement* cells, std::size_t n_cells, std::size_t n_points,
                                        const Layout& layout, const fs::path& file) {
  const auto offsets = array_values(required_array(cells, "offsets", file), n_cells, 1, layout, file);
  const auto types = array_values(required_array(cells, "types", file), n_cells, 1, layout, file);
  const double corners = offsets.empty() ? 0 : offsets.back();
  if (!(corners >= 0 && corners < 1e15)) data_error(file, "the last cell offset " + std::to_string(corners) + " is not a corner count");
  const auto connectivity = array_values(required_array(cells, "connectivity", file), static_cast<std::size_t>(corners), 1, layout, file);
  std::vector<Eigen::Vector3i> triangles;
  double begin = 0;
  for (std::size_t c = 0; c < n_cells; ++c) {
    const int type = static_cast<int>(types[c]);
    if (type != 5 && type != 7 && type != 9) {
      data_error(file, "cell " + std::to_string(c) + " has VTK type " + std::to_string(type) +
                           "; expected a surface: triangle (5), polygon (7) or quad (9)");
    }
    if (!(offsets[c] >= begin + 3 && offsets[c] <= corners)) data_error(file, "cell " + std::to_string(c) + "'s offset " + std::to_string(offsets[c]) + " does not give it 3 corners or more");
    const auto first = static_cast<std::size_t>(begin), last = static_cast<std::size_t>(offsets[c]);
    for (std::size_t k = first; k < last; ++k) {
      if (!(connectivity[k] >= 0 && connectivity[k] < static_cast<double>(n_points))) {
        data_error(file, "cell " + std::to_string(c) + " uses point " + std::to_string(connectivity[k]) + "; the piece has " + std::to_string(n_points));
      }
    }
    for (std::size_t k = first + 1; k + 1 < last; ++k) {
      triangles.emplace_back(int(connectivity[first]), int(connectivity[k]), int(connectivity[k + 1]));
    }
    begin = offsets[c];
  }
  return triangles;
}

/// `values` (3 per point) as vectors, refusing non-finite ones.
std::vector<Eigen::Vector3d> vectors(const std::vector<double>& values, const fs::path& file, const char* name) {
  std::vector<Eigen::Vector3d> out(values.size() / 3);
  for (std::size_t v = 0; v < out.size(); ++v) {
    out[v] = Eigen::Vector3d(values[3 * v], values[3 * v + 1], values[3 * v + 2]);
    if (!out[v].allFinite()) data_error(file, std::string(name) + " of point " + std::to_string(v) + " is not finite");
  }
  return out;
}

/// A piece's count attribute: a number of points or cells, not negative.
std::size_t count_attribute(const XMLElement* piece, const char* name, const fs::path& file) {
  std::int64_t n = -1;
  if (piece->QueryInt64Attribute(name, &n) != tinyxml2::XML_SUCCESS || n < 0) {
    data_error(file, std::string("the piece's ") + name + " is missing or not a count");
  }
  return static_cast<std::size_t>(n);
}

Piece read_piece(const fs::path& file, int piece_index) {
  const auto doc = load(file, "UnstructuredGrid", "");
  const XMLElement* root = doc->RootElement();
  const Layout layout = layout_of(root, file);
  const XMLElement* piece = choose_piece(child(root, "UnstructuredGrid", file), piece_index, file);
  const std::size_t n_points = count_attribute(piece, "NumberOfPoints", file);
  const std::size_t n_cells = count_attribute(piece, "NumberOfCells", file);
  Piece out;
  const XMLElement* points = child(child(piece, "Points", file), "DataArray", file);
  out.points = vectors(array_values(points, n_points, 3, layout, file), file, "the position");
  out.triangles = read_cells(child(piece, "Cells", file), n_cells, n_points, layout, file);
  const XMLElement* point_data = piece->FirstChildElement("PointData");
  if (const XMLElement* d = find_array(point_data, "displacement")) {
    out.displacement = vectors(array_values(d, n_points, 3, layout, file), file, "the displacement");
  }
  if (const XMLElement* r = find_array(point_data, "region")) {
    for (double v : array_values(r, n_points, 1, layout, file)) {
      if (!(v >= -1 && v < 1e6 && v == std::floor(v))) data_error(file, "region " + std::to_string(v) + " is not a region index (-1 or more)");
      out.region.push_back(static_cast<int>(v));
    }
  }
  return out;
}

/// Parts "region_<n>" for the regions present, ascending, and each vertex's part.
void region_parts(const std::vector<int>& region, AnimatedSurface& out) {
  if (region.empty()) return;
  std::vector<int> present;
  for (int r : region) {
    if (r >= 0) present.push_back(r);
  }
  std::sort(present.begin(), present.end());
  present.erase(std::unique(present.begin(), present.end()), present.end());
  for (int r : present) out.parts.push_back("region_" + std::to_string(r));
  for (int r : region) {
    out.vertex_part.push_back(r < 0 ? -1 : static_cast<int>(std::lower_bound(present.begin(), present.end(), r) - present.begin()));
  }
}

}  // namespace

AnimatedSurface read_vtu_series(const fs::path& pvd, int piece) {
  const std::vector<Frame> frames = read_collection(pvd);
  AnimatedSurface out;
  out.file = pvd.string();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (const auto reason = unreadable_file_reason(frames[f].file)) {
      throw Error(ExitCode::kNoInput, pvd.string() + ": cannot read frame " + std::to_string(f) + ", " +
                                          frames[f].file.string() + ": it is " + *reason);
    }
    Piece p = read_piece(frames[f].file, piece);
    if (f == 0) {
      out.rest = p.points;
      // The recorded rest comes back exactly where the writer subtracted it.
      for (std::size_t v = 0; v < p.displacement.size(); ++v) out.rest[v] -= p.displacement[v];
      out.triangles = p.triangles;
      region_parts(p.region, out);
    } else if (p.points.size() != out.rest.size() || p.triangles != out.triangles) {
      data_error(frames[f].file, "frame " + std::to_string(f) + " has " + std::to_string(p.points.size()) + " points and " +
                                     std::to_string(p.triangles.size()) + " triangles, the first frame " +
                                     std::to_string(out.rest.size()) + " and " + std::to_string(out.triangles.size()) +
                                     ": every frame must be the same mesh, with the same cells");
    }
    out.times.push_back(frames[f].time_s);
    out.poses.push_back(std::move(p.points));
  }
  const std::size_t n = out.times.size();
  // The last frame lasts as long as the one before it.
  out.duration = out.times[n - 1] + (n > 1 ? out.times[n - 1] - out.times[n - 2] : 0.0);
  out.in_seconds = true;
  return out;
}

}  // namespace systole::mesh
