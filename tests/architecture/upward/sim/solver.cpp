// A planted violation for architecture.includes_catch_an_upward_include: the simulator
// must not include the renderer (cmake/Architecture.cmake).
#include "render/renderer.h"
