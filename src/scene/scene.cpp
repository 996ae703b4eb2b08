#include "scene/scene.h"

#include <cmath>

namespace systole::scene {

int Output::frame_count() const { return static_cast<int>(std::lround(duration_s * fps)); }

}  // namespace systole::scene
