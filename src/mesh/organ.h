#pragma once
// From a scene's organ entry to its surface in world space, with its regions.

#include <vector>

#include "mesh/geometry.h"
#include "scene/organ.h"

namespace systole::mesh {

/// Loads the organ's file (already resolved by scene::load) or generates it, applies
/// units, centring and the transform, inspects it, and assigns regions. Throws
/// Error(kDataError) naming the organ when the surface is unusable (no triangles) or a
/// region selects nothing / names a part the mesh does not have (listing the parts).
OrganGeometry build_organ_geometry(const scene::Organ& organ);

/// Per-vertex region index (or -1) for the regions in order, a later region taking the
/// vertices it selects from an earlier one. Selectors act on `mesh` as given.
std::vector<int> assign_regions(const OrganMesh& mesh, const std::vector<scene::Region>& regions);

}  // namespace systole::mesh
