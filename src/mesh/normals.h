#pragma once
// Per-frame vertex normals of a deforming surface.

#include <Eigen/Core>
#include <vector>

namespace systole::mesh {

/// Area-weighted vertex normals (unit length; zero-area neighbourhoods give (0,0,1)).
/// `xyz` holds 3 doubles per vertex; `normals_xyz` receives 3 floats per vertex.
/// Deterministic and allocation-free.
void vertex_normals(const double* xyz, int vertex_count, const std::vector<Eigen::Vector3i>& triangles,
                    float* normals_xyz);

}  // namespace systole::mesh
