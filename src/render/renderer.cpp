#include "render/renderer.h"

// Only libOSMesa is linked: it exports the GL 4.5 entry points itself. Linking libGL as
// well would bind every gl* symbol to it and silently do nothing (DESIGN.md section 8).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "common/error.h"
#include "render/camera_matrices.h"
#include "render/shader_source.h"

namespace systole::render {
namespace {

// Attribute locations, as in shaders/organ.vert.glsl.
constexpr GLuint kPositionAttrib = 0;
constexpr GLuint kNormalAttrib = 1;
constexpr GLuint kColorAttrib = 2;

// Hemisphere ambient, linear RGB: a cool sky and a warm bounce from below (the body cavity).
const Eigen::Vector3f kSkyAmbient(0.09f, 0.10f, 0.11f);
const Eigen::Vector3f kGroundAmbient(0.035f, 0.022f, 0.02f);

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
  if (location < 0) fail(std::string("uniform ") + name + " not found in the organ shader");
  return location;
}

/// The organ shader compiled for one light count. The count is a compile-time constant
/// because llvmpipe runs a loop with a uniform bound (and the uniform-array indexing in it)
/// far slower than an unrolled one: 2.4x the whole draw of a 720p heart (docs/performance.md).
struct OrganProgram {
  GLuint id = 0;
  struct {
    GLint view_projection, camera_position, light_to_light, light_radiance, up, specular, shininess;
  } loc{};

  void create(int light_count) {
    id = link_program("organ.vert.glsl", "organ.frag.glsl",
                      "#define LIGHT_COUNT " + std::to_string(light_count) + "\n");
    loc.view_projection = uniform(id, "u_view_projection");
    loc.camera_position = uniform(id, "u_camera_position");
    loc.up = uniform(id, "u_up");
    loc.specular = uniform(id, "u_specular");
    loc.shininess = uniform(id, "u_shininess");
    // Without lights these are compiled out (-1: glUniform then does nothing).
    loc.light_to_light = glGetUniformLocation(id, "u_light_to_light");
    loc.light_radiance = glGetUniformLocation(id, "u_light_radiance");
    glUseProgram(id);
    glUniform3fv(uniform(id, "u_sky"), 1, kSkyAmbient.data());
    glUniform3fv(uniform(id, "u_ground"), 1, kGroundAmbient.data());
  }
};

/// A framebuffer with a colour and a depth renderbuffer (depth only when `with_depth`).
struct Framebuffer {
  GLuint fbo = 0;
  GLuint color = 0;
  GLuint depth = 0;

  void create(int width, int height, int samples, bool with_depth) {
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    if (with_depth) {
      glGenRenderbuffers(1, &depth);
      glBindRenderbuffer(GL_RENDERBUFFER, depth);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    }
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      fail("framebuffer incomplete (status 0x" + std::to_string(status) + ") at " +
           std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(samples) +
           " samples");
    }
  }

  void destroy() noexcept {
    if (depth) glDeleteRenderbuffers(1, &depth);
    if (color) glDeleteRenderbuffers(1, &color);
    if (fbo) glDeleteFramebuffers(1, &fbo);
    *this = Framebuffer{};
  }
};

struct Surface {
  GLuint vao = 0;
  GLuint positions = 0;  ///< float xyz per vertex, rewritten every frame.
  GLuint normals = 0;    ///< float xyz per vertex, rewritten every frame.
  GLuint colors = 0;     ///< float sRGB per vertex, static.
  GLuint indices = 0;    ///< uint32 x 3 per triangle, static.
  GLsizei index_count = 0;
  std::size_t vertex_count = 0;
  float specular = 0;
  float shininess = 1;
  bool uploaded = false;         ///< update_surface has given it positions.
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero();  ///< Bounds of the last upload. unit: m
  Eigen::Vector3d box_max = Eigen::Vector3d::Zero();
};

}  // namespace

struct Renderer::Impl {
  int width = 0;
  int height = 0;
  int samples = 0;
  OSMesaContext context = nullptr;
  mutable std::array<std::uint8_t, 4> tiny_buffer{};  ///< The 1x1 default framebuffer; we draw into FBOs.
  Framebuffer multisampled;                   ///< Drawn into when samples > 0.
  Framebuffer resolved;                       ///< Read back; drawn into directly when samples == 0.
  /// Index: light count; linked on first use, so at most once per count.
  std::array<OrganProgram, kMaxLights + 1> programs{};
  std::vector<Surface> surfaces;

  void make_current() const {
    if (OSMesaGetCurrentContext() == context) return;
    if (!OSMesaMakeCurrent(context, tiny_buffer.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      fail("OSMesaMakeCurrent failed");
    }
  }

  GLuint draw_fbo() const { return samples > 0 ? multisampled.fbo : resolved.fbo; }

  /// Frees everything; never throws (it runs in the destructor). GL objects die with the
  /// context anyway, but deleting them first keeps a context-sharing future honest.
  void release() noexcept {
    if (!context) return;
    const bool current = OSMesaGetCurrentContext() == context ||
                         OSMesaMakeCurrent(context, tiny_buffer.data(), GL_UNSIGNED_BYTE, 1, 1);
    if (current) release_gl_objects();
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);  // Unbind so no thread keeps a dangling context.
    OSMesaDestroyContext(context);
    context = nullptr;
  }

  void release_gl_objects() noexcept {
    for (Surface& s : surfaces) {
      const GLuint buffers[] = {s.positions, s.normals, s.colors, s.indices};
      glDeleteBuffers(4, buffers);
      glDeleteVertexArrays(1, &s.vao);
    }
    surfaces.clear();
    for (OrganProgram& p : programs) {
      if (p.id) glDeleteProgram(p.id);
    }
    multisampled.destroy();
    resolved.destroy();
  }
};

Renderer::Renderer(int width, int height, int msaa_samples) : impl_(std::make_unique<Impl>()) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384) {
    throw Error(ExitCode::kUsage, "render: image size " + std::to_string(width) + "x" +
                                      std::to_string(height) + " is out of range (1 to 16384)");
  }
  if (msaa_samples != 0 && msaa_samples != 2 && msaa_samples != 4) {
    throw Error(ExitCode::kUsage, "render: antialias must be 0, 2 or 4 samples, not " +
                                      std::to_string(msaa_samples));
  }
  Impl& r = *impl_;
  r.width = width;
  r.height = height;
  r.samples = msaa_samples;
  r.context = create_context();
  try {
    r.make_current();
    GLint max_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (msaa_samples > max_samples) {
      throw Error(ExitCode::kUsage, "render: " + std::to_string(msaa_samples) +
                                        " antialiasing samples asked, the driver offers at most " +
                                        std::to_string(max_samples));
    }
    r.resolved.create(width, height, 0, /*with_depth=*/msaa_samples == 0);
    if (msaa_samples > 0) r.multisampled.create(width, height, msaa_samples, /*with_depth=*/true);

    // Linked now so a broken shader fails at set-up; other light counts link on first use.
    constexpr int kDefaultLights = 2;  // scene's default_lights(): a key and a fill.
    r.programs[kDefaultLights].create(kDefaultLights);

    // Fixed state: it never changes between frames, and this context is ours alone.
    glBindFramebuffer(GL_FRAMEBUFFER, r.draw_fbo());
    glViewport(0, 0, width, height);  // The context was made current on a 1x1 buffer.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glDisable(GL_DITHER);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    check_gl("renderer set-up");
  } catch (...) {
    r.release();
    throw;
  }
}

Renderer::~Renderer() { impl_->release(); }

GlInfo Renderer::info() const {
  impl_->make_current();
  const auto text = [](GLenum name) {
    const GLubyte* value = glGetString(name);
    return value ? std::string(reinterpret_cast<const char*>(value)) : std::string();
  };
  return GlInfo{text(GL_VENDOR), text(GL_RENDERER), text(GL_VERSION),
                text(GL_SHADING_LANGUAGE_VERSION)};
}

int Renderer::add_surface(const std::vector<Eigen::Vector3i>& triangles,
                          const std::vector<scene::Color>& vertex_colors,
                          const scene::Material& material) {
  Impl& r = *impl_;
  const std::size_t vertex_count = vertex_colors.size();
  if (vertex_count == 0 || vertex_count > std::numeric_limits<std::uint32_t>::max()) {
    fail("a surface needs between 1 and 2^32-1 vertices, got " + std::to_string(vertex_count));
  }
  if (triangles.size() * 3 > static_cast<std::size_t>(std::numeric_limits<GLsizei>::max())) {
    fail("too many triangles in one surface: " + std::to_string(triangles.size()));
  }
  std::vector<std::uint32_t> indices;
  indices.reserve(triangles.size() * 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = triangles[t][k];
      if (v < 0 || static_cast<std::size_t>(v) >= vertex_count) {
        fail("triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
             " of a surface with " + std::to_string(vertex_count) + " vertices");
      }
      indices.push_back(static_cast<std::uint32_t>(v));
    }
  }
  std::vector<float> colors;
  colors.reserve(vertex_count * 3);
  for (const scene::Color& c : vertex_colors) {
    for (int k = 0; k < 3; ++k) colors.push_back(static_cast<float>(std::clamp(c[k], 0.0, 1.0)));
  }

  r.make_current();
  Surface s;
  s.vertex_count = vertex_count;
  s.index_count = static_cast<GLsizei>(indices.size());
  s.specular = static_cast<float>(std::max(material.specular, 0.0));
  s.shininess = static_cast<float>(std::max(material.shininess, 1.0));
  const auto bytes = static_cast<GLsizeiptr>(vertex_count * 3 * sizeof(float));

  glGenVertexArrays(1, &s.vao);
  glBindVertexArray(s.vao);
  const auto attribute = [&](GLuint& buffer, GLuint location, const void* data, GLenum usage) {
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, bytes, data, usage);
    glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    glEnableVertexAttribArray(location);
  };
  attribute(s.positions, kPositionAttrib, nullptr, GL_DYNAMIC_DRAW);
  attribute(s.normals, kNormalAttrib, nullptr, GL_DYNAMIC_DRAW);
  attribute(s.colors, kColorAttrib, colors.data(), GL_STATIC_DRAW);
  glGenBuffers(1, &s.indices);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.indices);  // Recorded in the VAO.
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
               indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  check_gl("add_surface");
  r.surfaces.push_back(s);
  return static_cast<int>(r.surfaces.size() - 1);
}

void Renderer::update_surface(int id, const float* positions_xyz, const float* normals_xyz) {
  Impl& r = *impl_;
  if (id < 0 || static_cast<std::size_t>(id) >= r.surfaces.size()) {
    fail("update_surface: unknown surface id " + std::to_string(id));
  }
  if (!positions_xyz || !normals_xyz) fail("update_surface: null positions or normals");
  Surface& s = r.surfaces[static_cast<std::size_t>(id)];

  // The bounds fit the depth range; the same pass rejects non-finite positions, which
  // would otherwise rasterize as garbage instead of stopping with a message.
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Vector3f hi = -lo;
  bool finite = true;
  for (std::size_t v = 0; v < s.vertex_count; ++v) {
    const Eigen::Map<const Eigen::Vector3f> p(positions_xyz + 3 * v);
    finite &= p.allFinite();
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (!finite) fail("update_surface: surface " + std::to_string(id) + " has non-finite positions");
  s.box_min = lo.cast<double>();
  s.box_max = hi.cast<double>();

  r.make_current();
  const auto bytes = static_cast<GLsizeiptr>(s.vertex_count * 3 * sizeof(float));
  glBindBuffer(GL_ARRAY_BUFFER, s.positions);
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, positions_xyz);
  glBindBuffer(GL_ARRAY_BUFFER, s.normals);
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, normals_xyz);
  s.uploaded = true;
}

void Renderer::draw(const scene::Camera& camera, const std::vector<scene::Light>& lights,
                    const scene::Color& background) {
  Impl& r = *impl_;
  if (lights.size() > static_cast<std::size_t>(kMaxLights)) {
    throw Error(ExitCode::kDataError, "render: at most " + std::to_string(kMaxLights) +
                                          " lights are supported, the scene has " +
                                          std::to_string(lights.size()));
  }
  const Eigen::Matrix4d view = look_at(camera);  // Validates the camera.

  // Everything drawn, as one sphere around the union of the surfaces' boxes.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Surface& s : r.surfaces) {
    if (!s.uploaded) continue;
    lo = lo.cwiseMin(s.box_min);
    hi = hi.cwiseMax(s.box_max);
  }
  BoundingSphere bounds;
  if (lo.allFinite() && hi.allFinite()) bounds = {(lo + hi) / 2, (hi - lo).norm() / 2};
  const DepthRange depth = fit_depth_range(camera, bounds);
  const Eigen::Matrix4f view_projection =
      (perspective(camera.fov_rad, static_cast<double>(r.width) / r.height, depth) * view).cast<float>();

  std::array<float, 3 * kMaxLights> to_light{};
  std::array<float, 3 * kMaxLights> radiance{};
  int light_count = 0;
  for (const scene::Light& light : lights) {
    const double length = light.direction.norm();
    if (!(length > 0) || !std::isfinite(length)) continue;  // No direction, no light.
    const Eigen::Vector3d l = -light.direction / length;   // Towards the light.
    for (int k = 0; k < 3; ++k) {
      to_light[3 * light_count + k] = static_cast<float>(l[k]);
      radiance[3 * light_count + k] =
          static_cast<float>(srgb_to_linear(light.color[k]) * std::max(light.intensity, 0.0));
    }
    ++light_count;
  }
  const Eigen::Vector3f eye = camera.position_m.cast<float>();
  const Eigen::Vector3f up = view.block<1, 3>(1, 0).transpose().cast<float>();

  r.make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, r.draw_fbo());
  // The framebuffer holds sRGB-encoded values (the shader encodes), so the background
  // is cleared as given.
  glClearColor(static_cast<float>(background.x()), static_cast<float>(background.y()),
               static_cast<float>(background.z()), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  OrganProgram& program = r.programs[static_cast<std::size_t>(light_count)];
  if (!program.id) program.create(light_count);
  glUseProgram(program.id);
  glUniformMatrix4fv(program.loc.view_projection, 1, GL_FALSE, view_projection.data());
  glUniform3fv(program.loc.camera_position, 1, eye.data());
  glUniform3fv(program.loc.up, 1, up.data());
  glUniform3fv(program.loc.light_to_light, std::max(light_count, 1), to_light.data());
  glUniform3fv(program.loc.light_radiance, std::max(light_count, 1), radiance.data());
  for (const Surface& s : r.surfaces) {
    if (!s.uploaded) continue;
    glUniform1f(program.loc.specular, s.specular);
    glUniform1f(program.loc.shininess, s.shininess);
    glBindVertexArray(s.vao);
    glDrawElements(GL_TRIANGLES, s.index_count, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
  glFinish();
  check_gl("draw");
}

void Renderer::read_frame(Image& out) {
  Impl& r = *impl_;
  r.make_current();
  if (r.samples > 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, r.multisampled.fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.resolved.fbo);
    glBlitFramebuffer(0, 0, r.width, r.height, 0, 0, r.width, r.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, r.resolved.fbo);
  const std::size_t row_bytes = static_cast<std::size_t>(r.width) * 3;
  if (out.width != r.width || out.height != r.height || out.rgb.size() != row_bytes * r.height) {
    out = Image(r.width, r.height);
  }
  glReadPixels(0, 0, r.width, r.height, GL_RGB, GL_UNSIGNED_BYTE, out.rgb.data());
  glBindFramebuffer(GL_FRAMEBUFFER, r.draw_fbo());
  check_gl("read_frame");
  // GL's row 0 is the bottom one; ours is the top.
  for (int y = 0; y < r.height / 2; ++y) {
    std::uint8_t* top = out.row(y);
    std::swap_ranges(top, top + row_bytes, out.row(r.height - 1 - y));
  }
}

}  // namespace systole::render
