#include "scene/scene.h"

#include <cmath>

namespace systole::scene {

int Output::frame_count() const { return static_cast<int>(std::lround(duration_s * fps * slow_motion)); }

double Output::frame_period_s() const {
  // A loop's frames split its length exactly, so frame frame_count() is frame 0 again.
  if (loop && frame_count() > 0) return duration_s / frame_count();
  return 1.0 / (fps * slow_motion);
}

}  // namespace systole::scene
