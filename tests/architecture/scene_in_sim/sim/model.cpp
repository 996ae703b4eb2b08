// A planted violation for architecture.includes_catch_scene_in_sim: only sim/from_scene.*
// may include the scene (cmake/Architecture.cmake).
#include "scene/scene.h"
