#pragma once
// Colouring of constraints so that no two of one colour share a particle.

#include <vector>

namespace systole::sim {

/// Greedy colouring of the pairs (a[i], b[i]) in index order: each pair gets the lowest
/// colour not yet used by a pair touching either particle. Deterministic. Returns the
/// colour of each pair.
std::vector<int> color_pairs(const std::vector<int>& a, const std::vector<int>& b, int particle_count);

}  // namespace systole::sim
