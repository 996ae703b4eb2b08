#include "sim/graph_coloring.h"

#include <algorithm>

namespace systole::sim {

std::vector<int> color_pairs(const std::vector<int>& a, const std::vector<int>& b, int particle_count) {
  std::vector<std::vector<int>> used(particle_count);  // Colours already touching each particle.
  std::vector<int> color(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto& ua = used[a[i]];
    const auto& ub = used[b[i]];
    int c = 0;
    while (std::find(ua.begin(), ua.end(), c) != ua.end() || std::find(ub.begin(), ub.end(), c) != ub.end()) ++c;
    color[i] = c;
    used[a[i]].push_back(c);
    used[b[i]].push_back(c);
  }
  return color;
}

}  // namespace systole::sim
