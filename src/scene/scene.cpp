#include "scene/scene.h"

#include <cmath>

namespace systole::scene {

int Output::frame_count() const { return static_cast<int>(std::lround(duration_s * fps * slow_motion)); }

double Output::frame_period_s() const {
  // A loop's frames split its length exactly, so frame frame_count() is frame 0 again.
  if (loop && frame_count() > 0) return duration_s / frame_count();
  return 1.0 / (fps * slow_motion);
}

double Output::organ_time_s(int frame) const { return (start_frame + frame) * frame_period_s(); }

bool anything_can_move(const Scene& scene) {
  if (!scene.interactions.empty()) return true;
  const auto drives = [](const Drive& d) { return d.waveform != Waveform::kNone && d.amplitude > 0; };
  for (const Organ& organ : scene.organs) {
    if (drives(organ.body.volume_drive)) return true;
    if (organ.regions.empty() && scene.gravity.squaredNorm() > 0) return true;  // One passive body.
    for (const Region& region : organ.regions) {
      if (drives(region.drive) || !region.motion.empty()) return true;
      if (!region.pinned && scene.gravity.squaredNorm() > 0) return true;
    }
  }
  return false;
}

std::vector<PixelRect> view_rectangles(int width, int height, int view_count) {
  std::vector<PixelRect> rects;
  if (view_count < 1) return rects;
  const int columns = view_count <= 3 ? view_count : static_cast<int>(std::ceil(std::sqrt(view_count)));
  const int rows = (view_count + columns - 1) / columns;
  for (int i = 0; i < view_count; ++i) {
    const int column = i % columns, row = i / columns;
    // Edges at exact integer fractions of the frame: neighbours share them, nothing is lost.
    const int x0 = column * width / columns, x1 = (column + 1) * width / columns;
    const int y0 = row * height / rows, y1 = (row + 1) * height / rows;
    rects.push_back({x0, y0, x1 - x0, y1 - y0});
  }
  return rects;
}

}  // namespace systole::scene
