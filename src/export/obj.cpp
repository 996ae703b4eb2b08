#include <cstdio>

#include "common/atomic_output.h"
#include "export/point_cache.h"

namespace systole::exporter {

void write_obj(const std::filesystem::path& file, const OrganTrack& organ) {
  write_atomically(file, [&](std::ostream& out) {
    out << "# " << organ.name << ": the rest mesh of Systole's point caches (metres, Y up)\n";
    out << "o " << organ.name << "\n";
    char line[128];
    // Nine significant digits: a float32 read back from the text is the float32 written.
    for (Eigen::Index v = 0; v < organ.rest_m.cols(); ++v) {
      const Eigen::Vector3f x = organ.rest_m.col(v).cast<float>();
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(x[0]), double(x[1]), double(x[2]));
      out << line;
    }
    for (const auto& t : organ.triangles) {
      std::snprintf(line, sizeof line, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
      out << line;
    }
  });
}

}  // namespace systole::exporter
