#include "common/atomic_output.h"
#include "export/point_cache.h"
#include "export/byte_order.h"

namespace systole::exporter {

void write_mdd(const std::filesystem::path& file, const OrganTrack& organ, double fps) {
  write_atomically(file, [&](std::ostream& out) {
    const auto frames = static_cast<std::uint32_t>(organ.frames_m.size());
    put_be32(out, frames);
    put_be32(out, static_cast<std::uint32_t>(organ.vertex_count()));
    // Each frame's time in the video. unit: s
    for (std::uint32_t f = 0; f < frames; ++f) put_be32(out, float_bits(static_cast<float>(f / fps)));
    for (const auto& x : organ.frames_m) {
      for (Eigen::Index i = 0; i < x.size(); ++i) put_be32(out, float_bits(static_cast<float>(x.data()[i])));
    }
  });
}

}  // namespace systole::exporter
