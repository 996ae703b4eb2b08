#include "render/shader_source.h"

#include <string>

#include "common/error.h"

namespace systole::render {

std::string_view shader_source(std::string_view name) {
  for (const EmbeddedShader& shader : embedded_shaders()) {
    if (shader.name == name) return shader.source;
  }
  throw Error(ExitCode::kInternal,
              "shader '" + std::string(name) + "' was not embedded (is shaders/" +
                  std::string(name) + " missing?)");
}

}  // namespace systole::render
