#include <cstring>

#include "common/atomic_output.h"
#include "export/point_cache.h"
#include "export/byte_order.h"

namespace systole::exporter {

void write_pc2(const std::filesystem::path& file, const OrganTrack& organ) {
  write_atomically(file, [&](std::ostream& out) {
    out.write("POINTCACHE2\0", 12);
    put_le32(out, 1);  // version
    put_le32(out, static_cast<std::uint32_t>(organ.vertex_count()));
    // Sample k is frame k: the cache starts at frame 0, one sample per frame.
    put_le32(out, float_bits(0.0f));
    put_le32(out, float_bits(1.0f));
    put_le32(out, static_cast<std::uint32_t>(organ.frames_m.size()));
    for (const auto& x : organ.frames_m) {
      for (Eigen::Index i = 0; i < x.size(); ++i) put_le32(out, float_bits(static_cast<float>(x.data()[i])));
    }
  });
}

std::vector<std::filesystem::path> write_point_caches(const std::filesystem::path& file, const Recording& rec) {
  std::vector<std::filesystem::path> written;
  const bool mdd = file.extension() == ".mdd";
  for (std::size_t o = 0; o < rec.organs.size(); ++o) {
    const auto cache = organ_file(file, rec, o);
    auto obj = cache;
    obj.replace_extension(".obj");
    write_obj(obj, rec.organs[o]);
    if (mdd) {
      write_mdd(cache, rec.organs[o], rec.fps);
    } else {
      write_pc2(cache, rec.organs[o]);
    }
    written.push_back(cache);
    written.push_back(obj);
  }
  return written;
}

}  // namespace systole::exporter
