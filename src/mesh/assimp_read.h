#pragma once
// Reading a file with assimp within bounds: the one way mesh/ calls Importer::ReadFile.

#include <filesystem>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

namespace systole::mesh {

/// Reads `file` (already through check_mesh_file), refuses a scene graph over the import
/// limits (mesh/file_bounds.h: its node count and depth, counted without recursion), then
/// applies `post_processing`. assimp's readers and steps recurse through the graph and
/// through nested data, so all of it runs on a thread with a 256 MiB stack (reserved, not
/// used): a deep file is refused with its depth instead of overflowing the process's stack.
/// The scene belongs to `importer`. Throws Error(kDataError) naming the file.
const aiScene* read_with_assimp(Assimp::Importer& importer, const std::filesystem::path& file, unsigned post_processing);

}  // namespace systole::mesh
