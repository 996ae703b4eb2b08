#include "clip/bake.h"

#include <chrono>

#include "world/bake.h"
#include "world/frame_source.h"

namespace systole::clip {

double bake_clip(const scene::Scene& scene, const std::filesystem::path& file, ProgressStyle style,
                 const std::string& label) {
  const auto start = std::chrono::steady_clock::now();
  world::FrameSource source(scene);
  const int frames = scene.output.frame_count();
  world::BakeWriter writer(file, scene, source.world());
  Eigen::Matrix3Xd positions;
  Progress progress(label, frames, style);
  // The writer is a listener on the run: every frame's organs, in order.
  source.on_frame([&](int frame) {
    for (std::size_t o = 0; o < source.world().organs.size(); ++o) {
      source.positions(static_cast<int>(o), positions);
      writer.write(positions);
    }
    progress.update(frame + 1);
  });
  source.advance_to(frames - 1);
  writer.commit();
  progress.finish();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace systole::clip
