// assimp is reached only from this file and animation.cpp: the rest of mesh/ sees OrganMesh.
#include "mesh/import.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "common/error.h"
#include "common/input_file.h"
#include "mesh/weld.h"

// assimp 5.2 as Debian builds it (ASSIMP_BUILD_DEBUG) ends the process on an internal
// assertion that malformed files reach: fuzz_mesh found a PLY whose broken face list trips
// TriangulateProcess (fuzz/regressions/mesh/). This definition takes the place of the
// library's (ELF symbol interposition: libassimp calls it through its PLT, and the
// executable's definition wins) and throws instead, which Importer::ReadFile catches and
// reports as a failed read: the file is refused with an error rather than aborting.
namespace Assimp {
void aiAssertViolation(const char* expression, const char* file, int line) {
  throw std::runtime_error(std::string("internal check failed reading the file (") + expression + " at " + file + ":" +
                           std::to_string(line) + ")");
}
}  // namespace Assimp

namespace systole::mesh {
namespace {

// The name of the first node (depth first) that references mesh `index`, or "".
std::string node_name_of_mesh(const aiNode* node, unsigned index) {
  if (node == nullptr) return "";
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    if (node->mMeshes[i] == index && node->mName.length > 0) return node->mName.C_Str();
  }
  for (unsigned i = 0; i < node->mNumChildren; ++i) {
    std::string name = node_name_of_mesh(node->mChildren[i], index);
    if (!name.empty()) return name;
  }
  return "";
}

// Drops vertices no triangle uses (stray points in OBJ files), keeping the order.
void drop_unused_vertices(OrganMesh& mesh) {
  std::vector<int> remap(mesh.surface.positions.size(), -1);
  for (const Eigen::Vector3i& t : mesh.surface.triangles) {
    for (int k = 0; k < 3; ++k) remap[static_cast<size_t>(t[k])] = 0;
  }
  int next = 0;
  for (size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] < 0) continue;
    remap[v] = next;
    mesh.surface.positions[static_cast<size_t>(next)] = mesh.surface.positions[v];
    mesh.vertex_part[static_cast<size_t>(next)] = mesh.vertex_part[v];
    ++next;
  }
  mesh.surface.positions.resize(static_cast<size_t>(next));
  mesh.vertex_part.resize(static_cast<size_t>(next));
  for (Eigen::Vector3i& t : mesh.surface.triangles) {
    for (int k = 0; k < 3; ++k) t[k] = remap[static_cast<size_t>(t[k])];
  }
  for (auto& membership : mesh.also_in) membership.first = remap[static_cast<size_t>(membership.first)];
  mesh.normalize_membership();  // Drops the pairs of removed vertices (now -1).
}

/// The parts a file's author named, as OrganMesh parts: every mesh by its name, a mesh of
/// several primitives also by the name they share (assimp reads glTF primitives as meshes
/// "name-0", "name-1", ...), every node by its name with the meshes it and its children hold
/// (so a group node is the union of its parts), and every material by its name.
class FileParts {
 public:
  explicit FileParts(OrganMesh& mesh) : mesh_(mesh) {}

  /// Mesh `index` holds vertices [first, first + count): its own name is their first part.
  void add_mesh(unsigned index, const std::string& name, int first, int count) {
    ranges_.resize(std::max<std::size_t>(ranges_.size(), index + 1), {0, 0});
    ranges_[index] = {first, count};
    const int part = part_named(name);
    for (int v = first; v < first + count; ++v) mesh_.vertex_part.push_back(part);
  }

  /// A further name for the vertices of meshes `indices`.
  void add_name(const std::string& name, const std::vector<unsigned>& indices) {
    if (name.empty()) return;
    const int part = part_named(name);
    for (unsigned index : indices) {
      if (index >= ranges_.size()) continue;
      const auto [first, count] = ranges_[index];
      for (int v = first; v < first + count; ++v) mesh_.also_in.emplace_back(v, part);
    }
  }

  /// Node names: each node names the meshes it and its descendants hold. Returns those.
  std::vector<unsigned> add_nodes(const aiNode* node) {
    std::vector<unsigned> held;
    if (node == nullptr) return held;
    for (unsigned i = 0; i < node->mNumMeshes; ++i) held.push_back(node->mMeshes[i]);
    for (unsigned i = 0; i < node->mNumChildren; ++i) {
      const std::vector<unsigned> below = add_nodes(node->mChildren[i]);
      held.insert(held.end(), below.begin(), below.end());
    }
    if (node->mParent != nullptr) add_name(node->mName.C_Str(), held);  // The root is the whole file.
    return held;
  }

 private:
  int part_named(const std::string& name) {
    int part = mesh_.part_index(name);  // Meshes of the same name form one part.
    if (part < 0) {
      part = static_cast<int>(mesh_.part_names.size());
      mesh_.part_names.push_back(name);
    }
    return part;
  }

  OrganMesh& mesh_;
  std::vector<std::pair<int, int>> ranges_;  // Per assimp mesh: first vertex, count.
};

/// "heart-2" -> "heart" (the name assimp gives a glTF mesh's third primitive), or "".
std::string primitive_base(const std::string& name) {
  const auto dash = name.rfind('-');
  if (dash == std::string::npos || dash == 0 || dash + 1 == name.size()) return {};
  for (std::size_t i = dash + 1; i < name.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return {};
  }
  return name.substr(0, dash);
}

void check_readable(const std::filesystem::path& file) {
  if (const auto reason = unreadable_file_reason(file)) {
    throw Error(ExitCode::kNoInput, file.string() + ": cannot read the mesh file: it is " + *reason);
  }
  std::ifstream probe(file, std::ios::binary);
  if (!probe) throw Error(ExitCode::kNoInput, file.string() + ": cannot read mesh file");
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
double ply_body_bytes(const std::string& header_text, bool& ascii) {
  std::istringstream header(header_text);
  ascii = false;
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
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
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
  const double min_body_bytes = ply_body_bytes(head.substr(0, end), ascii);
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
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
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
}

// A binary glTF whose header claims more bytes than the file holds makes assimp 5.2 allocate
// the claim (1.7 GB for a 600-byte file, found by fuzz_mesh; fuzz/regressions/mesh/). The
// header (magic "glTF", version, total length, then the first chunk's length) is checked
// against the file's size first; assimp recognizes GLB by that magic whatever the extension.
void check_glb_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char head[20] = {};
  in.read(reinterpret_cast<char*>(head), sizeof head);
  const std::streamsize got = in.gcount();
  if (got < 4 || std::memcmp(head, "glTF", 4) != 0) return;
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
}

}  // namespace

void check_mesh_file(const std::filesystem::path& file) {
  check_readable(file);
  check_ply_header(file);
  check_off_header(file);
  check_glb_header(file);
}

namespace {

// Reads the file with assimp: node transforms baked into the vertices, but meshes kept
// separate (not merged by material) so each keeps its name as a part.
const aiScene* read_scene(Assimp::Importer& importer, const std::filesystem::path& file) {
  importer.SetPropertyInteger(AI_CONFIG_PP_PTV_KEEP_HIERARCHY, 1);
  // Points and lines are split off by SortByPType and then skipped below.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, 0);
  const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                         aiProcess_SortByPType | aiProcess_ValidateDataStructure;
  const aiScene* scene = importer.ReadFile(file.string(), flags);
  if (scene == nullptr) {
    throw Error(ExitCode::kDataError,
                file.string() + ": cannot read as a mesh (assimp: " + importer.GetErrorString() + ")");
  }
  return scene;
}

// Base names shared by several primitives, and material names, each with its meshes.
struct SharedNames {
  std::map<std::string, std::vector<unsigned>> primitives;
  std::map<std::string, std::vector<unsigned>> materials;
};

// Appends every triangle mesh of the scene to the surface, in assimp's order, each a part.
SharedNames append_meshes(const aiScene* scene, const std::filesystem::path& file, TriangleMesh& surface,
                          FileParts& parts) {
  SharedNames shared_names;
  std::map<std::string, std::vector<unsigned>>& primitives = shared_names.primitives;
  std::map<std::string, std::vector<unsigned>>& materials = shared_names.materials;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* source = scene->mMeshes[m];
    if (source == nullptr || !(source->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    std::string name = source->mName.C_Str();
    if (name.empty()) name = node_name_of_mesh(scene->mRootNode, m);
    if (name.empty()) name = "mesh" + std::to_string(m);

    const int base = static_cast<int>(surface.positions.size());
    for (unsigned v = 0; v < source->mNumVertices; ++v) {
      const aiVector3D& p = source->mVertices[v];
      const Eigen::Vector3d position(p.x, p.y, p.z);
      if (!position.allFinite()) {
        throw Error(ExitCode::kDataError, file.string() + ": mesh '" + name + "' has a non-finite vertex coordinate");
      }
      surface.positions.push_back(position);
    }
    parts.add_mesh(m, name, base, static_cast<int>(source->mNumVertices));
    if (const std::string shared = primitive_base(name); !shared.empty()) primitives[shared].push_back(m);
    if (source->mMaterialIndex < scene->mNumMaterials) {
      aiString material;
      if (scene->mMaterials[source->mMaterialIndex]->Get(AI_MATKEY_NAME, material) == AI_SUCCESS) {
        materials[material.C_Str()].push_back(m);
      }
    }
    for (unsigned f = 0; f < source->mNumFaces; ++f) {
      const aiFace& face = source->mFaces[f];
      if (face.mNumIndices != 3) continue;  // A point or line left in a mixed mesh.
      Eigen::Vector3i triangle;
      for (int k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= source->mNumVertices) {
          throw Error(ExitCode::kDataError, file.string() + ": mesh '" + name + "' has a vertex index out of range");
        }
        triangle[k] = base + static_cast<int>(face.mIndices[k]);
      }
      surface.triangles.push_back(triangle);
    }
  }
  return shared_names;
}

}  // namespace

OrganMesh import_mesh(const std::filesystem::path& file) {
  check_mesh_file(file);

  Assimp::Importer importer;  // No logger is created, so assimp prints nothing.
  const aiScene* scene = read_scene(importer, file);

  OrganMesh mesh;
  TriangleMesh& surface = mesh.surface;
  FileParts parts(mesh);
  const SharedNames names = append_meshes(scene, file, surface, parts);
  parts.add_nodes(scene->mRootNode);
  for (const auto& [name, meshes] : names.primitives) {
    if (meshes.size() > 1) parts.add_name(name, meshes);  // Two or more primitives of one mesh.
  }
  // assimp names a material it made up itself "DefaultMaterial": not the author's name.
  for (const auto& [name, meshes] : names.materials) {
    if (name != AI_DEFAULT_MATERIAL_NAME) parts.add_name(name, meshes);
  }
  mesh.normalize_membership();
  if (surface.triangles.empty()) {
    throw Error(ExitCode::kDataError, file.string() + ": the file holds no triangles");
  }

  const std::size_t read_triangles = surface.triangles.size();
  weld(mesh, default_weld_tolerance(surface));
  mesh.dropped_triangles = static_cast<int>(read_triangles - surface.triangles.size());
  if (surface.triangles.empty()) {
    throw Error(ExitCode::kDataError, file.string() + ": every triangle has zero size");
  }
  drop_unused_vertices(mesh);
  return mesh;
}

}  // namespace systole::mesh
