#include "mesh/file_bounds.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/warning.h"

namespace systole::mesh {

ImportLimits ImportLimits::none() {
  ImportLimits none;
  none.max_vertices = none.max_triangles = none.max_nodes = std::numeric_limits<std::int64_t>::max();
  none.max_node_depth = none.max_json_depth = std::numeric_limits<int>::max();
  return none;
}

ImportLimits& import_limits() {
  static ImportLimits limits;
  return limits;
}

std::string grouped(double count) {
  const std::string digits = std::to_string(static_cast<unsigned long long>(std::min(count, 1e18)));
  std::string text;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text.push_back(',');
    text.push_back(digits[i]);
  }
  return text;
}

namespace {

std::string lowercase_extension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

[[noreturn]] void over_limit(const std::filesystem::path& file, const std::string& what, double count, double limit,
                             const std::string& unit) {
  throw Error(ExitCode::kDataError, file.string() + ": " + what + " " + grouped(count) + " " + unit +
                                        "; a mesh file may hold at most " + grouped(limit) +
                                        " (docs/robustness.md); pass --allow-large to read it anyway");
}

/// Refuses counts a header declares (or a scan found) over the limits.
/// `source`: "the PLY header declares", "the OBJ file holds".
void check_counts(const std::filesystem::path& file, const std::string& source, double vertices, double faces) {
  const ImportLimits& limits = import_limits();
  const auto max_vertices = static_cast<double>(limits.max_vertices), max_faces = static_cast<double>(limits.max_triangles);
  if (vertices > max_vertices) over_limit(file, source, vertices, max_vertices, "vertices");
  if (faces > max_faces) over_limit(file, source, faces, max_faces, "faces");
}

// Bytes one value of a PLY property type takes at least: binary, its size; ASCII, a digit
// and a separator.
std::size_t ply_min_bytes(const std::string& type, bool ascii) {
  if (ascii) return 2;
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "double" || type == "float64") return 8;
  return 4;
}

// The least number of bytes the body of a PLY header's elements needs, and whether the
// body is ASCII: the guard against headers promising more than the file holds.
double ply_body_bytes(const std::string& header_text, bool& ascii, double& vertices, double& faces) {
  std::istringstream header(header_text);
  ascii = false;
  vertices = faces = 0;
  double min_body_bytes = 0, count = 0, element_bytes = 0;  // double: counts may be absurd
  for (std::string line, word; std::getline(header, line);) {
    std::istringstream words(line);
    words >> word;
    if (word == "format") {
      words >> word;
      ascii = word == "ascii";
    } else if (word == "element") {
      min_body_bytes += count * element_bytes;
      words >> word >> count;
      if (word == "vertex") vertices = count;
      if (word == "face") faces = count;
      element_bytes = 0;
    } else if (word == "property") {
      words >> word;
      if (word == "list") words >> word;  // the count's type: an empty list is just the count
      element_bytes += static_cast<double>(ply_min_bytes(word, ascii));
    }
  }
  min_body_bytes += count * element_bytes;
  return min_body_bytes;
}

// A NUL byte in an ASCII PLY (right after end_header, fuzz_mesh found) sends assimp's
// reader into an endless loop; ASCII PLY never holds one.
void check_no_nul(const std::filesystem::path& file) {
  std::ifstream whole(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(whole)), std::istreambuf_iterator<char>());
  if (const std::size_t at = bytes.find('\0'); at != std::string::npos) {
    throw Error(ExitCode::kDataError, file.string() + ": cannot read as a mesh (ASCII PLY with a NUL byte at offset " +
                                          std::to_string(at) + ")");
  }
}

// PLY files assimp 5.2 mishandles are refused before it sees them (found by
// fuzz_mesh and the invalid-input tests; fuzz/regressions/mesh/): without `end_header` its
// reader never returns, and a claim of 10 million vertices in a 200-byte file makes it
// allocate and process them all. assimp picks its PLY reader by extension or by the "ply"
// magic, so both are checked.
void check_ply_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string head(64 * 1024, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const std::string extension = lowercase_extension(file);
  if (extension != ".ply" && !head.starts_with("ply")) return;
  // `end_header` must be a line of its own: assimp's reader looks for it as a line, and
  // never ends on a header where it only appears inside another word ("floatend_header").
  std::size_t end = std::string::npos;
  for (std::size_t at = head.find("\nend_header"); at != std::string::npos; at = head.find("\nend_header", at + 1)) {
    const std::size_t after = at + 11;
    if (after == head.size() || std::string_view(" \t\r\n").find(head[after]) != std::string_view::npos) {
      end = at + 1;
      break;
    }
  }
  if (end == std::string::npos) {
    throw Error(ExitCode::kDataError, file.string() + ": cannot read as a mesh (PLY header without an end_header line)");
  }
  bool ascii = false;
  double vertices = 0, faces = 0;
  const double min_body_bytes = ply_body_bytes(head.substr(0, end), ascii, vertices, faces);
  if (ascii) check_no_nul(file);
  std::error_code ec;
  const double file_bytes = static_cast<double>(std::filesystem::file_size(file, ec));
  if (min_body_bytes > file_bytes) {
    std::ostringstream m;
    m << file.string() << ": cannot read as a mesh (the PLY header promises at least "
      << static_cast<unsigned long long>(std::min(min_body_bytes, 1e18)) << " bytes of elements; the file has "
      << static_cast<unsigned long long>(file_bytes) << ")";
    throw Error(ExitCode::kDataError, m.str());
  }
  check_counts(file, "the PLY header declares", vertices, faces);
}

// An OFF file whose counts promise more than the file holds makes assimp 5.2 allocate for
// them before reading a face (4 vertices and 42 quadrillion faces in 79 bytes, a 38 GB
// allocation, found by fuzz_mesh; fuzz/regressions/mesh/). A vertex line takes at least
// "0 0 0\n" and a face line "0\n", so the counts are checked against the file's size.
void check_off_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const std::string extension = lowercase_extension(file);
  std::istringstream words(head);
  std::string word;
  words >> word;
  for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".off" && !word.ends_with("off")) return;
  // The counts: the first three numbers after the keyword (comments start with '#').
  double counts[3] = {0, 0, 0};
  int found = 0;
  for (std::string line; found < 3 && std::getline(words, line);) {
    std::istringstream numbers(line.substr(0, line.find('#')));
    while (found < 3 && numbers >> counts[found]) ++found;
  }
  std::error_code ec;
  const double file_bytes = static_cast<double>(std::filesystem::file_size(file, ec));
  const double min_bytes = 6 * counts[0] + 2 * counts[1];
  if (found == 3 && min_bytes > file_bytes) {
    std::ostringstream m;
    m << file.string() << ": cannot read as a mesh (the OFF header promises " << counts[0] << " vertices and "
      << counts[1] << " faces, at least " << static_cast<unsigned long long>(std::min(min_bytes, 1e18))
      << " bytes; the file has " << static_cast<unsigned long long>(file_bytes) << ")";
    throw Error(ExitCode::kDataError, m.str());
  }
  if (found == 3) check_counts(file, "the OFF header declares", counts[0], counts[1]);
}

// A binary glTF whose header claims more bytes than the file holds makes assimp 5.2 allocate
// the claim (1.7 GB for a 600-byte file, found by fuzz_mesh; fuzz/regressions/mesh/). The
// header (magic "glTF", version, total length, then the first chunk's length) is checked
// against the file's size first; assimp recognizes GLB by that magic whatever the extension.
bool check_glb_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char head[20] = {};
  in.read(reinterpret_cast<char*>(head), sizeof head);
  const std::streamsize got = in.gcount();
  if (got < 4 || std::memcmp(head, "glTF", 4) != 0) return false;
  auto u32 = [&](int at) {
    return std::uint32_t{head[at]} | std::uint32_t{head[at + 1]} << 8 | std::uint32_t{head[at + 2]} << 16 |
           std::uint32_t{head[at + 3]} << 24;
  };
  std::error_code ec;
  const std::uintmax_t file_bytes = std::filesystem::file_size(file, ec);
  const std::string what = file.string() + ": cannot read as a mesh (binary glTF ";
  if (got < 20) throw Error(ExitCode::kDataError, what + "shorter than its 20-byte header)");
  if (u32(8) != file_bytes) {
    throw Error(ExitCode::kDataError, what + "header gives a length of " + std::to_string(u32(8)) + " bytes; the file has " +
                                          std::to_string(file_bytes) + ")");
  }
  if (std::uintmax_t{u32(12)} + 20 > file_bytes) {
    throw Error(ExitCode::kDataError, what + "first chunk claims " + std::to_string(u32(12)) + " bytes; the file has " +
                                          std::to_string(file_bytes) + " in all)");
  }
  return true;
}


// ---- OBJ: counted, since the format declares nothing ----

/// What a scan of an OBJ's records found.
struct ObjCounts {
  double vertices = 0, faces = 0;
  double declared_vertices = 0, declared_faces = 0;  // From exporters' comments ("# 2000000 faces").
  std::string last_line;                             // When the file does not end with a newline.
};

/// A comment such as "# 2000000 faces" or "# Vertices: 8": the count it declares for `noun`.
void read_declared(std::string_view comment, ObjCounts& counts) {
  std::string lower(comment);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::istringstream words(lower);
  std::vector<std::string> tokens;
  for (std::string w; words >> w;) tokens.push_back(w);
  auto number = [](const std::string& w, double& out) {
    if (w.empty() || !std::isdigit(static_cast<unsigned char>(w[0]))) return false;
    out = std::strtod(w.c_str(), nullptr);
    return true;
  };
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    double n = 0;
    const bool before = i + 1 < tokens.size() && number(tokens[i], n);  // "2000000 faces"
    const std::string& noun = before ? tokens[i + 1] : tokens[i];
    if (!before && !(i + 1 < tokens.size() && number(tokens[i + 1], n))) continue;  // "faces: 2000000"
    if (noun.starts_with("vert")) counts.declared_vertices = n;
    if (noun.starts_with("face") || noun.starts_with("triangle")) counts.declared_faces = n;
  }
}

ObjCounts scan_obj(const std::filesystem::path& file) {
  ObjCounts counts;
  std::ifstream in(file, std::ios::binary);
  std::string line;
  bool ended_with_newline = true;
  std::vector<char> buffer(1 << 20);
  auto take = [&](std::string_view record) {
    if (record.size() >= 2 && record[0] == 'v' && (record[1] == ' ' || record[1] == '\t')) ++counts.vertices;
    if (record.size() >= 2 && record[0] == 'f' && (record[1] == ' ' || record[1] == '\t')) ++counts.faces;
    if (!record.empty() && record[0] == '#' && counts.vertices + counts.faces == 0) read_declared(record.substr(1), counts);
  };
  while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0) {
    const std::string_view chunk(buffer.data(), static_cast<std::size_t>(in.gcount()));
    std::size_t from = 0;
    for (std::size_t nl = chunk.find('\n'); nl != std::string_view::npos; nl = chunk.find('\n', from)) {
      if (line.empty()) {
        take(chunk.substr(from, nl - from));
      } else {
        line.append(chunk.substr(from, nl - from));
        take(line);
        line.clear();
      }
      from = nl + 1;
    }
    // A record split across reads; only its start matters to the counts, so a line is kept
    // to at most a few hundred bytes (a huge "line" in a binary file costs nothing).
    line.append(chunk.substr(from, std::min<std::size_t>(chunk.size() - from, 256 - std::min<std::size_t>(line.size(), 256))));
    ended_with_newline = from == chunk.size();
  }
  if (!ended_with_newline && !line.empty()) {
    take(line);
    counts.last_line = line;
  }
  return counts;
}

/// Whether an OBJ record that ends the file without a newline stops short: fewer values
/// than its kind needs, or a last value cut inside ("1/", "0.5e").
bool cut_short(const std::string& record) {
  std::istringstream words(record);
  std::string kind;
  words >> kind;
  std::vector<std::string> values;
  for (std::string w; words >> w;) values.push_back(w);
  const std::size_t needs = kind == "v" || kind == "vn" || kind == "f" ? 3 : kind == "vt" ? 1 : 0;
  if (values.size() < needs) return true;
  if (values.empty()) return false;
  const char last = values.back().back();
  return last == '/' || last == '-' || last == '+' || last == '.' || last == 'e' || last == 'E';
}

// A record cut in the middle is a file cut short (an interrupted download or export): what
// assimp would read is an organ with a piece missing, drawn without a word, so it is refused.
// Comments that declare more than the file holds only warn: a file edited after export keeps
// its stale comments.
void check_obj(const std::filesystem::path& file) {
  if (lowercase_extension(file) != ".obj") return;
  const ObjCounts counts = scan_obj(file);
  check_counts(file, "the OBJ file holds", counts.vertices, counts.faces);
  if (!counts.last_line.empty() && cut_short(counts.last_line)) {
    throw Error(ExitCode::kDataError, file.string() + ": the file is cut short: its last line '" +
                                          counts.last_line.substr(0, 60) +
                                          "' stops in the middle of a record (an interrupted download or export?); "
                                          "export it again, or delete that line to use the rest");
  }
  if (counts.declared_faces > counts.faces || counts.declared_vertices > counts.vertices) {
    warn(file.string() + ": its comments declare " + grouped(counts.declared_vertices) + " vertices and " +
         grouped(counts.declared_faces) + " faces, and it holds " + grouped(counts.vertices) + " and " +
         grouped(counts.faces) + ": is it cut short?");
  }
}

// ---- STL: a binary file's triangle count is in its header ----

void check_stl(const std::filesystem::path& file) {
  if (lowercase_extension(file) != ".stl") return;
  std::ifstream in(file, std::ios::binary);
  unsigned char head[84] = {};
  in.read(reinterpret_cast<char*>(head), sizeof head);
  if (in.gcount() < 84 || std::memcmp(head, "solid", 5) == 0) return;  // ASCII: assimp reads what is there.
  const double triangles = double(head[80]) + 256.0 * head[81] + 65536.0 * head[82] + 16777216.0 * head[83];
  check_counts(file, "the STL header declares", 0, triangles);
  std::error_code ec;
  const double file_bytes = static_cast<double>(std::filesystem::file_size(file, ec));
  if (84 + 50 * triangles > file_bytes) {
    throw Error(ExitCode::kDataError, file.string() + ": the file is cut short: its header declares " + grouped(triangles) +
                                          " triangles, " + grouped(84 + 50 * triangles) + " bytes, and it has " +
                                          grouped(file_bytes));
  }
}

// ---- glTF: the node graph assimp walks recursively ----

/// The JSON text of a binary glTF's first chunk, or of a .gltf file; "" for neither.
std::string gltf_json(const std::filesystem::path& file, bool binary) {
  std::ifstream in(file, std::ios::binary);
  if (binary) {
    unsigned char head[20] = {};
    in.read(reinterpret_cast<char*>(head), sizeof head);
    const std::uint32_t length = std::uint32_t{head[12]} | std::uint32_t{head[13]} << 8 |
                                 std::uint32_t{head[14]} << 16 | std::uint32_t{head[15]} << 24;
    if (std::memcmp(head + 16, "JSON", 4) != 0) return {};  // assimp refuses it itself.
    std::string text(length, '\0');  // check_glb_header has held the length to the file's size.
    in.read(text.data(), length);
    text.resize(static_cast<std::size_t>(in.gcount()));
    return text;
  }
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// What the node graph's check needs of a glTF, gathered by a SAX reader: no document is
/// built, so the cost is one pass over the text (a DOM with a filter costs the square of a
/// long array's length in nlohmann 3.11), and the reader stops at the first limit broken.
class GltfGraph : public nlohmann::json_sax<nlohmann::json> {
 public:
  explicit GltfGraph(const ImportLimits& limits) : limits_(limits) {}

  std::vector<std::vector<std::size_t>> children;  ///< Per node.
  std::vector<std::int64_t> node_mesh;             ///< Per node: its mesh, or -1.
  std::vector<std::vector<std::size_t>> mesh_positions;  ///< Per mesh: its primitives' POSITION accessors.
  std::vector<double> accessor_count;              ///< Per accessor: its element count.
  std::vector<std::size_t> scene_roots;
  std::string broken;  ///< The limit the text broke, if it did ("" else).

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t n) override { return value() && index(n) && count(static_cast<double>(n)); }
  bool number_float(number_float_t x, const string_t&) override { return value() && count(x); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return value() && open(false); }
  bool key(string_t& name) override {
    frames_.back().key = name;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override {
    if (!value()) return false;
    if (at({"nodes", "#", "children"})) children[element(1)].clear();
    return open(true);
  }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  struct Frame {
    bool array = false;
    std::size_t index = 0;  ///< Arrays: the element being read, +1.
    std::string key;        ///< Objects: the key being read.
  };

  /// Whether the value being read is at `path` from the root: keys, or "#" for any element.
  bool at(std::initializer_list<std::string_view> path) const {
    if (frames_.size() != path.size()) return false;
    std::size_t f = 0;
    for (const std::string_view step : path) {
      const Frame& frame = frames_[f++];
      if (step == "#" ? !frame.array : frame.array || frame.key != step) return false;
    }
    return true;
  }
  std::size_t element(std::size_t frame) const { return frames_[frame].index - 1; }

  /// Every value: counts the element of the array it is in; a new node or mesh is sized.
  bool value() {
    if (frames_.empty() || !frames_.back().array) return true;
    ++frames_.back().index;
    if (at({"nodes", "#"})) {
      if (children.size() >= static_cast<std::size_t>(std::min<std::int64_t>(limits_.max_nodes, 1LL << 40))) {
        broken = "nodes";
        return false;
      }
      children.emplace_back();
      node_mesh.push_back(-1);
    }
    if (at({"meshes", "#"})) mesh_positions.emplace_back();
    if (at({"accessors", "#"})) accessor_count.push_back(0);
    return true;
  }
  bool index(std::uint64_t n) {
    const auto i = static_cast<std::size_t>(n);
    if (at({"nodes", "#", "mesh"})) node_mesh[element(1)] = static_cast<std::int64_t>(std::min<std::uint64_t>(n, 1ULL << 62));
    if (at({"nodes", "#", "children", "#"})) children[element(1)].push_back(i);
    if (at({"meshes", "#", "primitives", "#", "attributes", "POSITION"})) mesh_positions[element(1)].push_back(i);
    if (at({"scenes", "#", "nodes", "#"})) scene_roots.push_back(i);
    return true;
  }
  bool count(double n) {
    if (at({"accessors", "#", "count"})) accessor_count[element(1)] = n;
    return true;
  }
  bool open(bool array) {
    if (static_cast<int>(frames_.size()) >= limits_.max_json_depth) {
      broken = "json depth";
      return false;
    }
    frames_.push_back({array, 0, {}});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return true;
  }

  const ImportLimits& limits_;
  std::vector<Frame> frames_;
};

/// Walks the graph from its roots, depth first with an explicit stack: every node must be
/// reached once (glTF requires a tree), no deeper than the limit. Returns the vertices the
/// nodes place, each placement of a mesh counted.
double placed_vertices(const GltfGraph& graph, const ImportLimits& limits, const std::filesystem::path& file) {
  const std::string what = file.string() + ": cannot read as a mesh (glTF ";
  const std::size_t nodes = graph.children.size();
  std::vector<char> has_parent(nodes, 0), reached(nodes, 0), root_done(nodes, 0);
  for (const auto& children : graph.children) {
    for (const std::size_t child : children) {
      if (child < nodes) has_parent[child] = 1;
    }
  }
  std::vector<std::pair<std::size_t, int>> stack;  // node, depth
  for (std::size_t n = 0; n < nodes; ++n) {
    if (!has_parent[n]) stack.emplace_back(n, 1);
  }
  for (const std::size_t root : graph.scene_roots) {
    if (root < nodes) stack.emplace_back(root, 1);
  }
  double placed = 0;
  while (!stack.empty()) {
    const auto [n, depth] = stack.back();
    stack.pop_back();
    if (depth == 1) {
      if (root_done[n]) continue;  // A root listed twice (by a scene, and as parentless).
      root_done[n] = 1;
    }
    if (reached[n]) {
      throw Error(ExitCode::kDataError, what + "node " + std::to_string(n) +
                                            " is reached twice from the roots: the graph has a cycle or a shared child, "
                                            "and glTF requires a tree)");
    }
    reached[n] = 1;
    if (depth > limits.max_node_depth) {
      throw Error(ExitCode::kDataError, file.string() + ": the glTF scene graph nests nodes over " +
                                            std::to_string(limits.max_node_depth) +
                                            " levels deep; a mesh file may nest at most that many");
    }
    const std::int64_t mesh = graph.node_mesh[n];
    if (mesh >= 0 && static_cast<std::size_t>(mesh) < graph.mesh_positions.size()) {
      for (const std::size_t accessor : graph.mesh_positions[static_cast<std::size_t>(mesh)]) {
        if (accessor < graph.accessor_count.size()) placed += graph.accessor_count[accessor];
      }
    }
    for (const std::size_t child : graph.children[n]) {
      if (child < nodes) stack.emplace_back(child, depth + 1);
    }
  }
  // A cycle no root leads to is still walked by a reader that starts anywhere in it.
  for (std::size_t n = 0; n < nodes; ++n) {
    if (!reached[n]) {
      throw Error(ExitCode::kDataError, what + "node " + std::to_string(n) +
                                            " is part of a cycle: no root leads to it, and glTF requires a tree)");
    }
  }
  return placed;
}

void check_gltf(const std::filesystem::path& file, bool binary) {
  if (!binary && lowercase_extension(file) != ".gltf") return;
  const ImportLimits& limits = import_limits();
  const std::string what = file.string() + ": cannot read as a mesh (glTF ";
  GltfGraph graph(limits);
  const bool read = nlohmann::json::sax_parse(gltf_json(file, binary), &graph);
  if (graph.broken == "nodes") {
    throw Error(ExitCode::kDataError, file.string() + ": the glTF scene graph has over " + grouped(double(limits.max_nodes)) +
                                          " nodes; a mesh file may hold at most that many (docs/robustness.md); pass "
                                          "--allow-large to read it anyway");
  }
  if (graph.broken == "json depth") {
    throw Error(ExitCode::kDataError, what + "JSON nested over " + std::to_string(limits.max_json_depth) + " levels deep)");
  }
  if (!read) return;  // Not JSON: assimp says so in its own words.
  check_counts(file, "the glTF nodes place", placed_vertices(graph, limits, file), 0);
}

}  // namespace

void check_mesh_counts(const std::filesystem::path& file) {
  check_ply_header(file);
  check_off_header(file);
  check_obj(file);
  check_stl(file);
  check_gltf(file, check_glb_header(file));
}

}  // namespace systole::mesh
