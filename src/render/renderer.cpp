// render::Renderer's context, surfaces (their buffers, uploads, cuts and enclosed parts) and
// the read-back. draw() and its passes are in renderer_passes.cpp; the state both share is
// render/renderer_impl.h.

#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "common/error.h"
#include "render/gl_objects.h"
#include "render/renderer_impl.h"

namespace systole::render {
using namespace gl;  // render/gl_objects.h: the GL objects the surfaces use

gl::OrganProgram& Renderer::Impl::program(int light_count, int variant) {
  OrganProgram& p = programs[static_cast<std::size_t>(light_count)][static_cast<std::size_t>(variant)];
  if (!p.id) p.create(light_count, variant);
  return p;
}

void Renderer::Impl::make_current() const {
  if (OSMesaGetCurrentContext() == context) return;
  if (!OSMesaMakeCurrent(context, tiny_buffer.data(), GL_UNSIGNED_BYTE, 1, 1)) {
    fail("OSMesaMakeCurrent failed");
  }
}

// GL objects die with the context anyway, but deleting them first keeps a context-sharing
// future honest.
void Renderer::Impl::release() noexcept {
  if (!context) return;
  const bool current = OSMesaGetCurrentContext() == context ||
                       OSMesaMakeCurrent(context, tiny_buffer.data(), GL_UNSIGNED_BYTE, 1, 1);
  if (current) release_gl_objects();
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);  // Unbind so no thread keeps a dangling context.
  OSMesaDestroyContext(context);
  context = nullptr;
}

void Renderer::Impl::release_gl_objects() noexcept {
  for (Surface& s : surfaces) {
    const GLuint buffers[] = {s.positions, s.normals, s.colors, s.opacity, s.indices, s.outside_indices};
    glDeleteBuffers(6, buffers);
    glDeleteVertexArrays(1, &s.vao);
    if (s.outside_vao) glDeleteVertexArrays(1, &s.outside_vao);
  }
  surfaces.clear();
  for (auto& variants : programs) {
    for (OrganProgram& p : variants) {
      if (p.id) glDeleteProgram(p.id);
    }
  }
  if (oit.fbo) oit.destroy();
  multisampled.destroy();
  resolved.destroy();
}

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
    r.program(kDefaultLights, 0);

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

namespace {

/// The triangles' vertex indices, 3 per triangle, each checked against the vertex count.
std::vector<std::uint32_t> checked_indices(const std::vector<Eigen::Vector3i>& triangles, std::size_t vertex_count) {
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
  return indices;
}

/// sRGB per vertex, 3 floats each, clamped to [0, 1].
std::vector<float> clamped_colors(const std::vector<scene::Color>& vertex_colors) {
  std::vector<float> colors;
  colors.reserve(vertex_colors.size() * 3);
  for (const scene::Color& c : vertex_colors) {
    for (int k = 0; k < 3; ++k) colors.push_back(static_cast<float>(std::clamp(c[k], 0.0, 1.0)));
  }
  return colors;
}

/// Opacity per vertex, in [0, 1]: `vertex_opacity` where given, else the material's.
std::vector<float> clamped_opacity(const scene::Material& material, const std::vector<double>& vertex_opacity,
                                   std::size_t vertex_count) {
  std::vector<float> opacity(vertex_count, static_cast<float>(std::clamp(material.opacity, 0.0, 1.0)));
  for (std::size_t v = 0; v < vertex_opacity.size(); ++v) {
    opacity[v] = static_cast<float>(std::clamp(vertex_opacity[v], 0.0, 1.0));  // NaN-free: the scene is validated.
  }
  return opacity;
}

/// Makes the surface's vertex array: position and normal buffers to be filled every frame,
/// the static colours, opacities and indices.
void create_buffers(Surface& s, const std::vector<float>& colors, const std::vector<float>& opacity,
                    const std::vector<std::uint32_t>& indices) {
  const auto bytes = static_cast<GLsizeiptr>(s.vertex_count * 3 * sizeof(float));
  glGenVertexArrays(1, &s.vao);
  glBindVertexArray(s.vao);
  const auto attribute = [&](GLuint& buffer, GLuint location, const void* data, GLenum usage, int size = 3) {
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, bytes / 3 * size, data, usage);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, size * static_cast<GLsizei>(sizeof(float)), nullptr);
    glEnableVertexAttribArray(location);
  };
  attribute(s.positions, kPositionAttrib, nullptr, GL_DYNAMIC_DRAW);
  attribute(s.normals, kNormalAttrib, nullptr, GL_DYNAMIC_DRAW);
  attribute(s.colors, kColorAttrib, colors.data(), GL_STATIC_DRAW);
  attribute(s.opacity, kOpacityAttrib, opacity.data(), GL_STATIC_DRAW, 1);
  glGenBuffers(1, &s.indices);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.indices);  // Recorded in the VAO.
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
               indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

}  // namespace

int Renderer::add_surface(const std::vector<Eigen::Vector3i>& triangles,
                          const std::vector<scene::Color>& vertex_colors,
                          const scene::Material& material, const std::vector<double>& vertex_opacity) {
  Impl& r = *impl_;
  const std::size_t vertex_count = vertex_colors.size();
  if (!vertex_opacity.empty() && vertex_opacity.size() != vertex_count) {
    fail("add_surface: " + std::to_string(vertex_opacity.size()) + " opacities for " + std::to_string(vertex_count) +
         " vertices");
  }
  if (vertex_count == 0 || vertex_count > std::numeric_limits<std::uint32_t>::max()) {
    fail("a surface needs between 1 and 2^32-1 vertices, got " + std::to_string(vertex_count));
  }
  const std::vector<std::uint32_t> indices = checked_indices(triangles, vertex_count);
  const std::vector<float> colors = clamped_colors(vertex_colors);
  const std::vector<float> opacity = clamped_opacity(material, vertex_opacity, vertex_count);

  r.make_current();
  Surface s;
  s.vertex_count = vertex_count;
  s.min_opacity = *std::min_element(opacity.begin(), opacity.end());
  s.max_opacity = *std::max_element(opacity.begin(), opacity.end());
  s.index_count = static_cast<GLsizei>(indices.size());
  s.specular = static_cast<float>(std::max(material.specular, 0.0));
  s.shininess = static_cast<float>(std::max(material.shininess, 1.0));
  create_buffers(s, colors, opacity, indices);
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

void Renderer::update_colors(int id, const float* colors_rgb) {
  Impl& r = *impl_;
  if (id < 0 || static_cast<std::size_t>(id) >= r.surfaces.size()) {
    fail("update_colors: unknown surface id " + std::to_string(id));
  }
  if (!colors_rgb) fail("update_colors: null colours");
  const Surface& s = r.surfaces[static_cast<std::size_t>(id)];
  r.make_current();
  glBindBuffer(GL_ARRAY_BUFFER, s.colors);
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(s.vertex_count * 3 * sizeof(float)), colors_rgb);
}

void Renderer::set_two_sided(int id, int from_triangle) {
  Impl& r = *impl_;
  if (id < 0 || static_cast<std::size_t>(id) >= r.surfaces.size()) {
    fail("set_two_sided: unknown surface id " + std::to_string(id));
  }
  r.surfaces[static_cast<std::size_t>(id)].two_sided_from = from_triangle;
}

void Renderer::set_enclosed(int id, const std::vector<char>& enclosed) {
  Impl& r = *impl_;
  if (id < 0 || static_cast<std::size_t>(id) >= r.surfaces.size()) {
    fail("set_enclosed: unknown surface id " + std::to_string(id));
  }
  Surface& s = r.surfaces[static_cast<std::size_t>(id)];
  if (enclosed.size() * 3 != static_cast<std::size_t>(s.index_count)) {
    fail("set_enclosed: " + std::to_string(enclosed.size()) + " flags for " + std::to_string(s.index_count / 3) +
         " triangles");
  }
  r.make_current();
  std::vector<std::uint32_t> all(static_cast<std::size_t>(s.index_count));
  glBindVertexArray(s.vao);  // Its element buffer is the surface's indices.
  glGetBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(all.size() * sizeof(std::uint32_t)), all.data());
  glBindVertexArray(0);
  std::vector<std::uint32_t> outside;
  s.outside_triangles.clear();
  for (std::size_t t = 0; t < enclosed.size(); ++t) {
    if (enclosed[t]) continue;
    s.outside_triangles.push_back(static_cast<int>(t));
    outside.insert(outside.end(), all.begin() + static_cast<std::ptrdiff_t>(3 * t),
                   all.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  }
  if (!s.outside_vao) {
    glGenVertexArrays(1, &s.outside_vao);
    glBindVertexArray(s.outside_vao);
    const std::pair<GLuint, GLuint> attributes[] = {{s.positions, kPositionAttrib}, {s.normals, kNormalAttrib},
                                                    {s.colors, kColorAttrib}, {s.opacity, kOpacityAttrib}};
    for (const auto& [buffer, location] : attributes) {
      const GLint size = location == kOpacityAttrib ? 1 : 3;
      glBindBuffer(GL_ARRAY_BUFFER, buffer);
      glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, size * static_cast<GLsizei>(sizeof(float)), nullptr);
      glEnableVertexAttribArray(location);
    }
    glGenBuffers(1, &s.outside_indices);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.outside_indices);  // Recorded in the VAO.
  } else {
    glBindVertexArray(s.outside_vao);
  }
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(outside.size() * sizeof(std::uint32_t)), outside.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
  s.outside_index_count = static_cast<GLsizei>(outside.size());
  check_gl("set_enclosed");
}

void Renderer::set_clip(int id, const scene::ClipPlane& clip) {
  Impl& r = *impl_;
  if (id < 0 || static_cast<std::size_t>(id) >= r.surfaces.size()) {
    fail("set_clip: unknown surface id " + std::to_string(id));
  }
  r.surfaces[static_cast<std::size_t>(id)].clip = clip;
}

void Renderer::read_frame(Image& out) {
  Impl& r = *impl_;
  r.make_current();
  if (r.samples > 0 && !r.frame_resolved) {
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
