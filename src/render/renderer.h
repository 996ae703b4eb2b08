#pragma once
// The off-screen rasterizer: an OSMesa OpenGL 4.5 core-profile context drawing organ
// surfaces into a (multisampled) framebuffer, read back as an RGB image.
//
// Each Renderer owns its own context, so several may live in one process; a Renderer makes
// its context current on the calling thread at every call, and must be used by one thread
// at a time. llvmpipe's thread count is LP_NUM_THREADS, read when the first context of the
// process is created: the caller sets it.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "common/image.h"
#include "scene/scene.h"

namespace systole::render {

/// Most directional lights draw() shades with (one organ program is compiled per count).
inline constexpr int kMaxLights = 8;

struct GlInfo {
  std::string vendor;
  std::string renderer;      ///< e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string version;       ///< e.g. "4.5 (Core Profile) Mesa 22.3.6".
  std::string glsl_version;
};

/// One panel of the frame: a camera, the pixels it draws into and which surfaces it shows.
struct ViewDraw {
  scene::Camera camera;     ///< Already at the frame's time (app/camera_motion.h); only its pose and fov are read.
  scene::PixelRect rect;    ///< Where in the frame, top-left origin; width or height 0: the whole frame. unit: px
  std::vector<int> surfaces;  ///< Surface ids shown; empty: every surface.
  scene::ClipPlane clip;    ///< Cuts the view's surfaces that have no clip of their own (set_clip).
};

class Renderer {
 public:
  /// Creates the context and a width x height framebuffer with `msaa_samples` (0, 2 or 4).
  /// Throws Error(kInternal) when OSMesa or a shader fails, with the driver's log, and
  /// Error(kUsage) for a size or sample count it cannot make.
  Renderer(int width, int height, int msaa_samples);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  GlInfo info() const;

  /// Registers a surface whose topology never changes; returns its id (0, 1, ...).
  /// The vertex count is vertex_colors.size(); colours are sRGB per vertex (region colours),
  /// decoded to linear light in the shader. Triangles are counter-clockwise seen from
  /// outside (back faces are culled). The surface is drawn once update_surface gave it
  /// positions. Throws Error(kInternal) for an index out of range.
  /// `vertex_opacity` (unit: 1, in [0, 1]), when not empty, gives each vertex its opacity
  /// (region opacities); else every vertex has material.opacity. Parts below 1 are drawn
  /// with weighted blended order-independent transparency over the opaque ones.
  int add_surface(const std::vector<Eigen::Vector3i>& triangles,
                  const std::vector<scene::Color>& vertex_colors, const scene::Material& material,
                  const std::vector<double>& vertex_opacity = {});

  /// Replaces a surface's per-vertex sRGB colours, 3 floats per vertex (colour maps that
  /// change every frame). No GL allocation. Throws Error(kInternal) for an unknown id.
  void update_colors(int id, const float* colors_rgb);

  /// Cuts a surface with its own plane (clip.enabled false: none, the default). A cut
  /// surface is drawn without back-face culling, its back faces flat in clip.cut_color.
  void set_clip(int id, const scene::ClipPlane& clip);

  /// Draws the back faces of a surface's triangles from `from_triangle` on (0: all; -1, the
  /// default: none), shaded as the front with the normal turned towards the eye: an open
  /// surface (an atlas part, a sheet) shows its inside through its holes and from behind,
  /// instead of nothing. Closed pieces, listed first, keep back-face culling.
  void set_two_sided(int id, int from_triangle);

  /// Marks the triangles (indices into add_surface's list, one flag each) that the
  /// surface's own closed, opaque outside hides from any eye outside it: a heart's cavity
  /// linings and the valves between its chambers. A view draws them only where they can
  /// show: when it cuts the surface (its own clip or the view's), when any part of the
  /// surface is see-through, or when its eye or near plane reaches into the surface's
  /// bounds. Otherwise it draws the rest, in the same order, so the pixels are the same
  /// (tests/render: the linings cost a rasterizer as much as the outside, drawn behind it).
  /// Throws Error(kInternal) for an unknown id or a flag count that is not the triangle count.
  void set_enclosed(int id, const std::vector<char>& enclosed);

  /// Uploads a surface's current vertex positions (unit: m, world space) and unit normals,
  /// 3 floats per vertex, vertex count as given to add_surface. No GL allocation.
  /// Throws Error(kInternal) for an unknown id or a non-finite position.
  void update_surface(int id, const float* positions_xyz, const float* normals_xyz);

  /// Draws every surface and waits for the rasterizer to finish (so its cost is measured here).
  /// `background` is sRGB. Near and far planes follow the surfaces' bounding sphere.
  /// Throws Error(kDataError) for more than kMaxLights lights or a degenerate camera.
  void draw(const scene::Camera& camera, const std::vector<scene::Light>& lights,
            const scene::Color& background);

  /// Draws several views into one frame (split screen), each into its rectangle with its
  /// own depth range and aspect; then as draw() above. Throws Error(kDataError) for a
  /// rectangle outside the frame or an unknown surface id.
  void draw(const std::vector<ViewDraw>& views, const std::vector<scene::Light>& lights,
            const scene::Color& background);

  /// Reads the last frame back (resolving multisampling), top row first, into `out`
  /// (resized if needed; no allocation when it already has the right size).
  void read_frame(Image& out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace systole::render
