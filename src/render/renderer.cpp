#include "render/renderer.h"

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
#include "render/gl_objects.h"
#include "render/shader_source.h"

namespace systole::render {
using namespace gl;  // render/gl_objects.h: the GL objects the passes use

namespace {
struct PreparedView {
  Eigen::Matrix4f view_projection;
  Eigen::Vector3f eye, up;
  GLint x = 0, y = 0;  ///< GL viewport: bottom-left origin. unit: px
  GLsizei width = 0, height = 0;
  Eigen::Vector3d eye_m, forward;  ///< The camera's position and unit view direction.
  double near_m = 0;               ///< The near plane's distance along `forward`. unit: m
  const ViewDraw* source = nullptr;
};

struct Surface {
  GLuint vao = 0;
  GLuint positions = 0;  ///< float xyz per vertex, rewritten every frame.
  GLuint normals = 0;    ///< float xyz per vertex, rewritten every frame.
  GLuint colors = 0;     ///< float sRGB per vertex (update_colors rewrites it).
  GLuint opacity = 0;    ///< float per vertex, static.
  GLuint indices = 0;    ///< uint32 x 3 per triangle, static.
  GLsizei index_count = 0;
  std::size_t vertex_count = 0;
  float specular = 0;
  float shininess = 1;
  float min_opacity = 1;  ///< Below kOpaqueFrom: a part goes through the transparent pass.
  float max_opacity = 1;  ///< From kOpaqueFrom: a part goes through the opaque pass.
  scene::ClipPlane clip;  ///< The surface's own cut (set_clip).
  int two_sided_from = -1; ///< Back faces drawn from this triangle on (set_two_sided); -1: none.
  /// The triangles an outside view draws (set_enclosed): the others, in order, in their own
  /// index buffer and vertex array (the same attribute buffers). 0: none marked.
  GLuint outside_vao = 0;
  GLuint outside_indices = 0;
  GLsizei outside_index_count = 0;
  std::vector<int> outside_triangles;  ///< Their indices in the full list, ascending.
  bool uploaded = false;         ///< update_surface has given it positions.
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero();  ///< Bounds of the last upload. unit: m
  Eigen::Vector3d box_max = Eigen::Vector3d::Zero();
};

/// True when every corner of the surface's last bounds lies beyond the view's near plane:
/// nothing of it is cut by that plane, and the eye (depth 0) is outside it.
bool clear_of_near_plane(const Surface& s, const PreparedView& p) {
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d c((corner & 1) ? s.box_max.x() : s.box_min.x(), (corner & 2) ? s.box_max.y() : s.box_min.y(),
                            (corner & 4) ? s.box_max.z() : s.box_min.z());
    if (!(p.forward.dot(c - p.eye_m) > p.near_m)) return false;
  }
  return true;
}

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
  std::array<std::array<OrganProgram, kVariantCount>, kMaxLights + 1> programs{};
  std::vector<Surface> surfaces;
  OitTargets oit;                             ///< Made on the first transparent frame.
  std::vector<PreparedView> prepared;         ///< draw()'s per-view set-up, kept to avoid allocating per frame.
  bool frame_resolved = false;                ///< MSAA: draw() already resolved into `resolved`.

  OrganProgram& program(int light_count, int variant) {
    OrganProgram& p = programs[static_cast<std::size_t>(light_count)][static_cast<std::size_t>(variant)];
    if (!p.id) p.create(light_count, variant);
    return p;
  }

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

  std::vector<float> opacity(vertex_count, static_cast<float>(std::clamp(material.opacity, 0.0, 1.0)));
  for (std::size_t v = 0; v < vertex_opacity.size(); ++v) {
    opacity[v] = static_cast<float>(std::clamp(vertex_opacity[v], 0.0, 1.0));  // NaN-free: the scene is validated.
  }

  r.make_current();
  Surface s;
  s.vertex_count = vertex_count;
  s.min_opacity = *std::min_element(opacity.begin(), opacity.end());
  s.max_opacity = *std::max_element(opacity.begin(), opacity.end());
  s.index_count = static_cast<GLsizei>(indices.size());
  s.specular = static_cast<float>(std::max(material.specular, 0.0));
  s.shininess = static_cast<float>(std::max(material.shininess, 1.0));
  const auto bytes = static_cast<GLsizeiptr>(vertex_count * 3 * sizeof(float));

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

void Renderer::draw(const scene::Camera& camera, const std::vector<scene::Light>& lights,
                    const scene::Color& background) {
  ViewDraw whole;
  whole.camera = camera;
  draw(std::vector<ViewDraw>{whole}, lights, background);
}

void Renderer::draw(const std::vector<ViewDraw>& views, const std::vector<scene::Light>& lights,
                    const scene::Color& background) {
  Impl& r = *impl_;
  if (lights.size() > static_cast<std::size_t>(kMaxLights)) {
    throw Error(ExitCode::kDataError, "render: at most " + std::to_string(kMaxLights) +
                                          " lights are supported, the scene has " +
                                          std::to_string(lights.size()));
  }
  std::vector<PreparedView>& prepared = r.prepared;
  prepared.clear();
  for (const ViewDraw& v : views) {
    PreparedView p;
    p.source = &v;
    scene::PixelRect rect = v.rect;
    if (rect.width == 0 || rect.height == 0) rect = {0, 0, r.width, r.height};
    if (rect.x < 0 || rect.y < 0 || rect.width < 1 || rect.height < 1 || rect.x + rect.width > r.width ||
        rect.y + rect.height > r.height) {
      throw Error(ExitCode::kDataError, "render: a view's rectangle lies outside the " + std::to_string(r.width) +
                                            "x" + std::to_string(r.height) + " frame");
    }
    for (const int id : v.surfaces) {
      if (id < 0 || static_cast<std::size_t>(id) >= r.surfaces.size()) {
        throw Error(ExitCode::kDataError, "render: a view names unknown surface " + std::to_string(id));
      }
    }
    const Eigen::Matrix4d view = look_at(v.camera);  // Validates the camera.
    // Everything this view draws, as one sphere around the union of its surfaces' boxes.
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    const auto include = [&](const Surface& s) {
      if (!s.uploaded) return;
      lo = lo.cwiseMin(s.box_min);
      hi = hi.cwiseMax(s.box_max);
    };
    if (v.surfaces.empty()) {
      for (const Surface& s : r.surfaces) include(s);
    } else {
      for (const int id : v.surfaces) include(r.surfaces[static_cast<std::size_t>(id)]);
    }
    BoundingSphere bounds;
    if (lo.allFinite() && hi.allFinite()) bounds = {(lo + hi) / 2, (hi - lo).norm() / 2};
    const DepthRange depth = fit_depth_range(v.camera, bounds);
    p.view_projection =
        (perspective(v.camera.fov_rad, static_cast<double>(rect.width) / rect.height, depth) * view).cast<float>();
    p.eye = v.camera.position_m.cast<float>();
    p.eye_m = v.camera.position_m;
    p.forward = (v.camera.target_m - v.camera.position_m).normalized();
    p.near_m = depth.near_m;
    p.up = view.block<1, 3>(1, 0).transpose().cast<float>();
    p.x = rect.x;
    p.y = r.height - rect.y - rect.height;
    p.width = rect.width;
    p.height = rect.height;
    prepared.push_back(p);
  }

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

  // Draws the surfaces of view `p` that have a part in this pass.
  const auto draw_view = [&](const PreparedView& p, bool transparent_pass) {
    glViewport(p.x, p.y, p.width, p.height);
    const auto draw_one = [&](const Surface& s) {
      if (!s.uploaded) return;
      const bool has_transparent = s.min_opacity < kOpaqueFrom;
      if (transparent_pass ? !has_transparent : s.max_opacity < kOpaqueFrom) return;
      const scene::ClipPlane& clip = s.clip.enabled ? s.clip : p.source->clip;
      int variant = clip.enabled ? kClipVariant : 0;
      if (transparent_pass) variant |= kTransparentPartVariant;
      else if (has_transparent) variant |= kOpaquePartVariant;
      OrganProgram& program = r.program(light_count, variant);
      glUseProgram(program.id);
      glUniformMatrix4fv(program.loc.view_projection, 1, GL_FALSE, p.view_projection.data());
      glUniform3fv(program.loc.camera_position, 1, p.eye.data());
      glUniform3fv(program.loc.up, 1, p.up.data());
      glUniform3fv(program.loc.light_to_light, std::max(light_count, 1), to_light.data());
      glUniform3fv(program.loc.light_radiance, std::max(light_count, 1), radiance.data());
      glUniform1f(program.loc.specular, s.specular);
      glUniform1f(program.loc.shininess, s.shininess);
      if (clip.enabled) {
        const Eigen::Vector3d n = clip.normal.normalized();
        const Eigen::Vector4f plane(static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z()),
                                    static_cast<float>(-n.dot(clip.point_m)));
        const Eigen::Vector3f cut = clip.cut_color.cwiseMax(0.0).cwiseMin(1.0).cast<float>();
        glUniform4fv(program.loc.clip_plane, 1, plane.data());
        glUniform3fv(program.loc.cut_color, 1, cut.data());
        glEnable(GL_CLIP_DISTANCE0);
      }
      // The enclosed triangles (set_enclosed) are hidden by the outside when nothing cuts
      // it, every part is opaque and no part of it lies before the near plane (nor the eye
      // inside): then the rest is drawn, in the same order.
      const bool outside_only = s.outside_vao && !clip.enabled && !has_transparent && clear_of_near_plane(s, p);
      const GLsizei index_count = outside_only ? s.outside_index_count : s.index_count;
      // Through a cut the inside shows as the cut face; an open surface shows its back:
      // the triangles from two_sided_from on are drawn without culling.
      GLsizei culled = index_count;  // The indices drawn with back faces culled.
      if (clip.enabled) {
        culled = 0;
      } else if (s.two_sided_from >= 0) {
        const GLsizei before =
            outside_only ? static_cast<GLsizei>(std::lower_bound(s.outside_triangles.begin(), s.outside_triangles.end(),
                                                                 s.two_sided_from) -
                                                s.outside_triangles.begin())
                         : s.two_sided_from;
        culled = std::min<GLsizei>(3 * before, index_count);
      }
      const auto draw_triangles = [&] {
        if (culled > 0) glDrawElements(GL_TRIANGLES, culled, GL_UNSIGNED_INT, nullptr);
        if (culled < index_count) {
          glDisable(GL_CULL_FACE);
          glDrawElements(GL_TRIANGLES, index_count - culled, GL_UNSIGNED_INT,
                         reinterpret_cast<const void*>(static_cast<std::uintptr_t>(culled) * sizeof(std::uint32_t)));
          glEnable(GL_CULL_FACE);
        }
      };
      glBindVertexArray(outside_only ? s.outside_vao : s.vao);
      draw_triangles();
      if (clip.enabled) glDisable(GL_CLIP_DISTANCE0);
    };
    if (p.source->surfaces.empty()) {
      for (const Surface& s : r.surfaces) draw_one(s);
    } else {
      for (const int id : p.source->surfaces) draw_one(r.surfaces[static_cast<std::size_t>(id)]);
    }
  };

  r.make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, r.draw_fbo());
  glViewport(0, 0, r.width, r.height);
  // The framebuffer holds sRGB-encoded values (the shader encodes), so the background
  // is cleared as given.
  glClearColor(static_cast<float>(background.x()), static_cast<float>(background.y()),
               static_cast<float>(background.z()), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (const PreparedView& p : prepared) draw_view(p, false);

  // The pixels the transparent parts can touch: the union over views of their boxes'
  // projections (the whole view when a box reaches behind the eye), in GL pixels. The
  // OIT clear, accumulation and composite are scissored to it: llvmpipe pays per pixel.
  int x0 = r.width, y0 = r.height, x1 = 0, y1 = 0;
  for (const PreparedView& p : prepared) {
    const auto include = [&](const Surface& s) {
      if (!s.uploaded || !(s.min_opacity < kOpaqueFrom)) return;
      double lo_x = 1, lo_y = 1, hi_x = -1, hi_y = -1;  // NDC
      bool behind = false;
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d c((corner & 1) ? s.box_max.x() : s.box_min.x(), (corner & 2) ? s.box_max.y() : s.box_min.y(),
                                (corner & 4) ? s.box_max.z() : s.box_min.z());
        const Eigen::Vector4d clip = p.view_projection.cast<double>() * c.homogeneous();
        if (!(clip.w() > 1e-9)) {
          behind = true;
          break;
        }
        lo_x = std::min(lo_x, clip.x() / clip.w());
        hi_x = std::max(hi_x, clip.x() / clip.w());
        lo_y = std::min(lo_y, clip.y() / clip.w());
        hi_y = std::max(hi_y, clip.y() / clip.w());
      }
      if (behind) lo_x = lo_y = -1, hi_x = hi_y = 1;
      lo_x = std::max(lo_x, -1.0), lo_y = std::max(lo_y, -1.0), hi_x = std::min(hi_x, 1.0), hi_y = std::min(hi_y, 1.0);
      if (lo_x > hi_x || lo_y > hi_y) return;  // Off screen.
      // One pixel of margin for rasterization at the edges.
      x0 = std::min(x0, p.x + std::max(0, static_cast<int>(std::floor((lo_x + 1) / 2 * p.width)) - 1));
      y0 = std::min(y0, p.y + std::max(0, static_cast<int>(std::floor((lo_y + 1) / 2 * p.height)) - 1));
      x1 = std::max(x1, p.x + std::min(p.width, static_cast<int>(std::ceil((hi_x + 1) / 2 * p.width)) + 1));
      y1 = std::max(y1, p.y + std::min(p.height, static_cast<int>(std::ceil((hi_y + 1) / 2 * p.height)) + 1));
    };
    if (p.source->surfaces.empty()) {
      for (const Surface& s : r.surfaces) include(s);
    } else {
      for (const int id : p.source->surfaces) include(r.surfaces[static_cast<std::size_t>(id)]);
    }
  }
  const bool any_transparent = x1 > x0 && y1 > y0;
  r.frame_resolved = false;
  if (any_transparent) {
    // Weighted blended OIT: accumulate every transparent part against the opaque depth
    // (tested, not written), then composite over the opaque frame.
    if (!r.oit.fbo) {
      r.oit.create(r.width, r.height, r.samples, r.samples > 0 ? r.multisampled.depth : r.resolved.depth);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, r.oit.fbo);
    glViewport(0, 0, r.width, r.height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, y0, x1 - x0, y1 - y0);
    const float zero[] = {0, 0, 0, 0};
    const float one[] = {1, 1, 1, 1};
    glClearBufferfv(GL_COLOR, 0, zero);
    glClearBufferfv(GL_COLOR, 1, one);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
    for (const PreparedView& p : prepared) draw_view(p, true);
    glDepthMask(GL_TRUE);
    glDisable(GL_SCISSOR_TEST);  // Blits are scissored too: the opaque resolve needs every pixel.

    if (r.samples > 0) {  // Resolve the opaque frame and both OIT targets, then composite.
      glBindFramebuffer(GL_READ_FRAMEBUFFER, r.multisampled.fbo);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.resolved.fbo);
      glBlitFramebuffer(0, 0, r.width, r.height, 0, 0, r.width, r.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      glBindFramebuffer(GL_READ_FRAMEBUFFER, r.oit.fbo);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.oit.texture_fbo);
      for (const GLenum attachment : {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1}) {
        glReadBuffer(attachment);
        glDrawBuffer(attachment);
        glBlitFramebuffer(0, 0, r.width, r.height, 0, 0, r.width, r.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      }
      const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
      glReadBuffer(GL_COLOR_ATTACHMENT0);
      glDrawBuffers(2, both);
      r.frame_resolved = true;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, r.resolved.fbo);
    glEnable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(r.oit.composite_program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, r.oit.accumulation);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, r.oit.revealage);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(r.oit.empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, r.draw_fbo());
  }
  glBindVertexArray(0);
  glFinish();
  check_gl("draw");
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
