#pragma once
// The body of an organ whose generator brings its own volumetric myocardium (the anatomical
// heart, mesh/anatomy.h): the lattice nodes through its walls are the particles, the springs
// carry the fibre directions (active strain, sim/forces.h), and the drawn surface follows
// the lattice cell each vertex lies in.

#include "mesh/geometry.h"
#include "sim/params.h"
#include "sim/reduced.h"

namespace systole::sim {

/// Mass: the organ's mass spread by each node's share of the wall's volume. Stiffness: each
/// spring gets body.stiffness times its weight (its cells' volume over its length squared,
/// the mean weight 1), so the lattice is one material however its cells are shaped.
/// Regions: geometry.node_region. No volume constraint (the walls keep their own volume;
/// the cavities are free to empty). Same errors as build_model.
ReducedBody build_myocardium_model(const OrganParams& organ, const mesh::OrganGeometry& geometry,
                                   const ModelOptions& options);

}  // namespace systole::sim
