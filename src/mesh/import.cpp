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
#include <unordered_map>

#include "common/error.h"
#include "common/input_file.h"
#include "mesh/assimp_read.h"
#include "mesh/file_bounds.h"
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
    // Meshes of the same name form one part. Looked up by name, not by a search of the list:
    // an atlas of 20,000 parts would cost the square of that.
    const auto [at, added] = part_of_name_.try_emplace(name, static_cast<int>(mesh_.part_names.size()));
    if (added) mesh_.part_names.push_back(name);
    return at->second;
  }

  OrganMesh& mesh_;
  std::unordered_map<std::string, int> part_of_name_;
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

}  // namespace

void check_mesh_file(const std::filesystem::path& file) {
  check_readable(file);
  check_mesh_counts(file);
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
  return read_with_assimp(importer, file, flags);
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
