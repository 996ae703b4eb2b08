#include "mesh/mesh.h"

namespace systole::mesh {

int OrganMesh::part_index(const std::string& name) const {
  for (int i = 0; i < static_cast<int>(part_names.size()); ++i) {
    if (part_names[i] == name) return i;
  }
  return -1;
}

}  // namespace systole::mesh
