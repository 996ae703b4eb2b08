#pragma once
// GLSL sources from shaders/, embedded into the binary at build time
// (cmake/EmbedShaders.cmake), so an installed systole needs no source tree.

#include <string>
#include <string_view>
#include <vector>

namespace systole::render {

struct EmbeddedShader {
  std::string_view name;    ///< File name in shaders/, e.g. "organ.vert.glsl".
  std::string_view source;
};

const std::vector<EmbeddedShader>& embedded_shaders();

/// The source of shaders/<name>; throws Error(kInternal) if it was not embedded.
std::string_view shader_source(std::string_view name);

}  // namespace systole::render
