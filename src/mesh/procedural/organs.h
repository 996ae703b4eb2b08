#pragma once
// The generators behind generate_organ(): one file per organ in mesh/procedural/.

#include "mesh/mesh.h"

namespace systole::mesh::procedural {

/// About how many triangles a generator aims for at `detail` (1..6): 1200 * 2^(detail-1).
int target_triangles(int detail);

/// A heart, about 12 cm base to apex: +Y towards the head, +Z anterior (the viewer),
/// apex down, forward and to +X (the patient's left). Parts: left_ventricle,
/// right_ventricle, left_atrium, right_atrium, apex, aorta, pulmonary_trunk,
/// superior_vena_cava, inferior_vena_cava.
OrganMesh heart(int detail);

}  // namespace systole::mesh::procedural
