#pragma once
// What a mesh file may ask of the importer, checked before assimp reads it. assimp 5.2 trusts
// a file's counts and recurses through its scene graph, so a small file can make it allocate
// gigabytes, spin forever or overflow the stack (docs/robustness.md, "Mesh files"). Each
// check reads the file at most once, front to back, and refuses with the limit it broke.

#include <cstdint>
#include <filesystem>
#include <string>

namespace systole::mesh {

/// How much a mesh file may hold. The vertex limit is the world's (clip/limits.h), checked
/// here on the counts the file declares or holds, before the model exists.
struct ImportLimits {
  std::int64_t max_vertices = 2'000'000;   ///< Over the file, each placement of a mesh counted.
  std::int64_t max_triangles = 4'000'000;  ///< Faces (a closed surface has about twice its vertices).
  std::int64_t max_nodes = 10'000;         ///< Nodes of a scene graph (an atlas organ has tens).
  int max_node_depth = 256;                ///< Levels of nesting in it.
  int max_json_depth = 128;                ///< Nesting of a glTF's JSON (the format needs about 8).

  /// No limit (`--allow-large`); the graph's shape (a tree, no cycle) is still checked.
  static ImportLimits none();
};

/// The limits this process applies; `--allow-large` lifts them for the run.
ImportLimits& import_limits();

/// "2,100,000": a count as the limits' messages give it.
std::string grouped(double count);

/// Refuses a file whose headers promise more than it holds, more than the limits allow, or
/// that is cut short (an OBJ's last record stops midway, a binary STL holds fewer triangles
/// than its header), and warns (common/warning.h) when an OBJ's comments declare more than
/// it holds. Formats: PLY, OFF, OBJ, STL, glTF/GLB (its node graph: count, depth, a tree,
/// and the vertices its nodes place). Throws Error(kDataError) naming the file and the
/// limit or the cause.
void check_mesh_counts(const std::filesystem::path& file);

}  // namespace systole::mesh
