#pragma once
// An organ's surface in world space with its regions: what mesh/ hands the simulator.

#include <vector>

#include "mesh/inspect.h"
#include "mesh/mesh.h"

namespace systole::mesh {

struct OrganGeometry {
  OrganMesh mesh;                  ///< World space, metres.
  MeshReport report;               ///< What inspection found (after welding).
  std::vector<int> vertex_region;  ///< Per vertex: index into the organ's regions, or -1 (undriven body).
  /// Per myocardium node (mesh.anatomy), the same: the regions' selectors applied to the nodes.
  std::vector<int> node_region;
};

}  // namespace systole::mesh
