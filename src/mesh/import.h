#pragma once
// Mesh files through assimp: OBJ, STL, PLY, glTF/GLB and the rest assimp reads.

#include <filesystem>

#include "mesh/mesh.h"

namespace systole::mesh {

/// Loads every triangle of a file into one surface, in the file's own units, with each
/// sub-mesh (or its node's name when the mesh is unnamed) as a part, then welds coincident
/// vertices. Throws Error(kNoInput) when the file is missing or unreadable and
/// Error(kDataError) naming the file when assimp cannot parse it or it has no triangles.
OrganMesh import_mesh(const std::filesystem::path& file);

/// What import_mesh checks before assimp reads the file: that it is a readable regular file,
/// and that PLY and binary glTF headers do not promise more than the file holds (assimp 5.2
/// hangs or allocates the claim). Throws Error(kNoInput) or Error(kDataError) naming the file.
void check_mesh_file(const std::filesystem::path& file);

}  // namespace systole::mesh
