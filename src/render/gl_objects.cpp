#include "render/gl_objects.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "render/shader_source.h"

namespace systole::render::gl {

[[noreturn]] void fail(const std::string& what) { throw Error(ExitCode::kInternal, "render: " + what); }

double srgb_to_linear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

void check_gl(const char* where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) fail(std::string("OpenGL error 0x") + std::to_string(error) + " in " + where);
}

OSMesaContext create_context() {
  // Core profile 4.5 (what Mesa 22.3 offers); 3.3 still runs our #version 330 shaders.
  for (const int minor_major : {45, 33}) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                           OSMESA_DEPTH_BITS, 0,  // We draw into our own FBO.
                           OSMESA_STENCIL_BITS, 0,
                           OSMESA_ACCUM_BITS, 0,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, minor_major / 10,
                           OSMESA_CONTEXT_MINOR_VERSION, minor_major % 10,
                           0};
    if (OSMesaContext context = OSMesaCreateContextAttribs(attribs, nullptr)) return context;
  }
  fail("OSMesaCreateContextAttribs refused an OpenGL 4.5 and a 3.3 core-profile context");
}

/// Compiles shaders/<name> with `defines` ("#define X 1\n" lines) inserted after its
/// #version line, which must come first.
GLuint compile_shader(GLenum type, std::string_view name, std::string_view defines) {
  const std::string_view source = shader_source(name);
  const std::size_t body = std::min(source.find('\n'), source.size() - 1) + 1;
  const std::string_view parts[] = {source.substr(0, body), defines, source.substr(body)};
  const GLchar* texts[3];
  GLint lengths[3];
  for (int i = 0; i < 3; ++i) {
    texts[i] = parts[i].data();
    lengths[i] = static_cast<GLint>(parts[i].size());
  }
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 3, texts, lengths);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint log_length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &log_length);
    std::string log(static_cast<std::size_t>(std::max(log_length, 1)), '\0');
    glGetShaderInfoLog(shader, log_length, nullptr, log.data());
    glDeleteShader(shader);
    fail("shader " + std::string(name) + " failed to compile:\n" + log.c_str());
  }
  return shader;
}

GLuint link_program(std::string_view vertex_name, std::string_view fragment_name, std::string_view defines) {
  const GLuint vertex = compile_shader(GL_VERTEX_SHADER, vertex_name, defines);
  GLuint fragment = 0;
  try {
    fragment = compile_shader(GL_FRAGMENT_SHADER, fragment_name, defines);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);  // Flagged; freed with the program.
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint log_length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &log_length);
    std::string log(static_cast<std::size_t>(std::max(log_length, 1)), '\0');
    glGetProgramInfoLog(program, log_length, nullptr, log.data());
    glDeleteProgram(program);
    fail("shader program " + std::string(vertex_name) + " + " + std::string(fragment_name) +
         " failed to link:\n" + log.c_str());
  }
  return program;
}

GLint uniform(GLuint program, const char* name) {
  const GLint location = glGetUniformLocation(program, name);
  if (location < 0) fail(std::string("uniform ") + name + " not found in its shader");
  return location;
}

std::string variant_defines(int light_count, int variant) {
  std::string d = "#define LIGHT_COUNT " + std::to_string(light_count) + "\n";
  if (variant & kClipVariant) d += "#define CLIP 1\n";
  if (variant & (kOpaquePartVariant | kTransparentPartVariant)) d += "#define WITH_OPACITY 1\n";
  if (variant & kOpaquePartVariant) d += "#define OPAQUE_PART 1\n";
  if (variant & kTransparentPartVariant) d += "#define TRANSPARENT_PART 1\n";
  return d;
}

}  // namespace systole::render::gl
