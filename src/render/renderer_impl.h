#pragma once
// render::Renderer's private state, shared by its two halves: renderer.cpp (the context,
// the surfaces' buffers and uploads, the read-back) and renderer_passes.cpp (draw(): one
// frame's passes over a FrameState). Internal to render/.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/gl_objects.h"
#include "render/renderer.h"

namespace systole::render {

/// What draw() works out once per view before any GL call.
struct PreparedView {
  Eigen::Matrix4f view_projection;
  Eigen::Vector3f eye, up;
  GLint x = 0, y = 0;  ///< GL viewport: bottom-left origin. unit: px
  GLsizei width = 0, height = 0;
  Eigen::Vector3d eye_m, forward;  ///< The camera's position and unit view direction.
  double near_m = 0;               ///< The near plane's distance along `forward`. unit: m
  const ViewDraw* source = nullptr;
};

/// One registered surface: its GL buffers and how it is drawn.
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

/// A rectangle of GL pixels (bottom-left origin), [x0, x1) x [y0, y1). unit: px
struct ScreenBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return !(x1 > x0 && y1 > y0); }
};

/// What one frame's passes share, set up by draw() before the first GL call and then only
/// read: the views with their matrices, the lights, the background and the pixels the
/// transparent parts can touch. Kept in the Impl so a frame allocates nothing.
struct FrameState {
  std::vector<PreparedView> views;
  int light_count = 0;  ///< The lights with a direction (the program variant's count).
  std::array<float, 3 * kMaxLights> to_light{};  ///< Unit directions towards each light, world space.
  std::array<float, 3 * kMaxLights> radiance{};  ///< Linear RGB per light (colour x intensity).
  scene::Color background = scene::Color::Zero();  ///< sRGB, cleared as given.
  /// The union over views of the transparent parts' boxes' projections; empty: no
  /// transparent pass. The OIT clear, accumulation and composite are scissored to it.
  ScreenBox transparent_box;
};

struct Renderer::Impl {
  int width = 0;
  int height = 0;
  int samples = 0;
  OSMesaContext context = nullptr;
  mutable std::array<std::uint8_t, 4> tiny_buffer{};  ///< The 1x1 default framebuffer; we draw into FBOs.
  gl::Framebuffer multisampled;               ///< Drawn into when samples > 0.
  gl::Framebuffer resolved;                   ///< Read back; drawn into directly when samples == 0.
  /// Index: light count; linked on first use, so at most once per count.
  std::array<std::array<gl::OrganProgram, gl::kVariantCount>, kMaxLights + 1> programs{};
  std::vector<Surface> surfaces;
  gl::OitTargets oit;                         ///< Made on the first transparent frame.
  FrameState frame;                           ///< The current frame's (renderer_passes.cpp).
  bool frame_resolved = false;                ///< MSAA: draw() already resolved into `resolved`.

  gl::OrganProgram& program(int light_count, int variant);
  void make_current() const;
  GLuint draw_fbo() const { return samples > 0 ? multisampled.fbo : resolved.fbo; }
  /// Frees everything; never throws (it runs in the destructor).
  void release() noexcept;
  void release_gl_objects() noexcept;

  // renderer_passes.cpp: draw()'s steps, in the order it takes them.
  /// Fills `frame` (no GL call); throws for a bad light count, rectangle, surface or camera.
  void prepare_frame(const std::vector<ViewDraw>& views, const std::vector<scene::Light>& lights,
                     const scene::Color& background);
  /// Clears the frame and draws every view's opaque parts.
  void opaque_pass();
  /// Weighted blended OIT: every view's transparent parts into the accumulation targets.
  void transparent_pass();
  /// Resolves the opaque frame and the OIT targets (MSAA), then blends them over it.
  void composite_pass();
  /// Draws the surfaces of view `p` that have a part in the opaque or the transparent pass.
  void draw_view(const PreparedView& p, bool transparent_pass);
  void draw_surface(const PreparedView& p, const Surface& s, bool transparent_pass);
};

}  // namespace systole::render
