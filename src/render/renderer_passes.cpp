// render::Renderer::draw and its passes, in the order a frame takes them: prepare the frame
// state (no GL), the opaque pass, then, only when a transparent part is on screen, the
// weighted blended OIT accumulation and the composite. Overlays are drawn later, on the
// read-back image (overlay/), never here.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "common/error.h"
#include "render/camera_matrices.h"
#include "render/gl_objects.h"
#include "render/renderer.h"
#include "render/renderer_impl.h"

namespace systole::render {
using namespace gl;  // render/gl_objects.h: the GL objects the passes use

namespace {

/// Calls `f` with each surface view `v` shows, in its order (every surface when it names none).
template <class F>
void for_each_shown(const ViewDraw& v, const std::vector<Surface>& surfaces, F&& f) {
  if (v.surfaces.empty()) {
    for (const Surface& s : surfaces) f(s);
  } else {
    for (const int id : v.surfaces) f(surfaces[static_cast<std::size_t>(id)]);
  }
}

/// The view's rectangle (the whole frame when it has no size), checked against the frame,
/// with its surface ids. unit: px, top-left origin
scene::PixelRect checked_rect(const ViewDraw& v, int frame_width, int frame_height, std::size_t surface_count) {
  scene::PixelRect rect = v.rect;
  if (rect.width == 0 || rect.height == 0) rect = {0, 0, frame_width, frame_height};
  if (rect.x < 0 || rect.y < 0 || rect.width < 1 || rect.height < 1 || rect.x + rect.width > frame_width ||
      rect.y + rect.height > frame_height) {
    throw Error(ExitCode::kDataError, "render: a view's rectangle lies outside the " + std::to_string(frame_width) +
                                          "x" + std::to_string(frame_height) + " frame");
  }
  for (const int id : v.surfaces) {
    if (id < 0 || static_cast<std::size_t>(id) >= surface_count) {
      throw Error(ExitCode::kDataError, "render: a view names unknown surface " + std::to_string(id));
    }
  }
  return rect;
}

/// Everything view `v` draws, as one sphere around the union of its surfaces' boxes.
BoundingSphere view_bounds(const ViewDraw& v, const std::vector<Surface>& surfaces) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for_each_shown(v, surfaces, [&](const Surface& s) {
    if (!s.uploaded) return;
    lo = lo.cwiseMin(s.box_min);
    hi = hi.cwiseMax(s.box_max);
  });
  BoundingSphere bounds;
  if (lo.allFinite() && hi.allFinite()) bounds = {(lo + hi) / 2, (hi - lo).norm() / 2};
  return bounds;
}

/// A view's matrices, viewport and near plane; throws for a bad rectangle, surface or camera.
PreparedView prepare_view(const ViewDraw& v, int frame_width, int frame_height, const std::vector<Surface>& surfaces) {
  PreparedView p;
  p.source = &v;
  const scene::PixelRect rect = checked_rect(v, frame_width, frame_height, surfaces.size());
  const Eigen::Matrix4d view = look_at(v.camera);  // Validates the camera.
  const DepthRange depth = fit_depth_range(v.camera, view_bounds(v, surfaces));
  p.view_projection =
      (perspective(v.camera.fov_rad, static_cast<double>(rect.width) / rect.height, depth) * view).cast<float>();
  p.eye = v.camera.position_m.cast<float>();
  p.eye_m = v.camera.position_m;
  p.forward = (v.camera.target_m - v.camera.position_m).normalized();
  p.near_m = depth.near_m;
  p.up = view.block<1, 3>(1, 0).transpose().cast<float>();
  p.x = rect.x;
  p.y = frame_height - rect.y - rect.height;
  p.width = rect.width;
  p.height = rect.height;
  return p;
}

/// The lights with a direction, as the shader takes them: towards the light, linear radiance.
void pack_lights(const std::vector<scene::Light>& lights, FrameState& frame) {
  frame.to_light.fill(0);
  frame.radiance.fill(0);
  frame.light_count = 0;
  for (const scene::Light& light : lights) {
    const double length = light.direction.norm();
    if (!(length > 0) || !std::isfinite(length)) continue;  // No direction, no light.
    const Eigen::Vector3d l = -light.direction / length;   // Towards the light.
    const int i = frame.light_count;
    for (int k = 0; k < 3; ++k) {
      frame.to_light[3 * i + k] = static_cast<float>(l[k]);
      frame.radiance[3 * i + k] = static_cast<float>(srgb_to_linear(light.color[k]) * std::max(light.intensity, 0.0));
    }
    ++frame.light_count;
  }
}

/// Grows `box` by the GL pixels of view `p` that surface `s`'s bounds project to (the
/// whole view when they reach behind the eye), with one pixel of margin for rasterization.
void include_projected_box(const PreparedView& p, const Surface& s, ScreenBox& box) {
  const Eigen::Matrix4d view_projection = p.view_projection.cast<double>();
  double lo_x = 1, lo_y = 1, hi_x = -1, hi_y = -1;  // NDC
  bool behind = false;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d c((corner & 1) ? s.box_max.x() : s.box_min.x(), (corner & 2) ? s.box_max.y() : s.box_min.y(),
                            (corner & 4) ? s.box_max.z() : s.box_min.z());
    const Eigen::Vector4d clip = view_projection * c.homogeneous();
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
  box.x0 = std::min(box.x0, p.x + std::max(0, static_cast<int>(std::floor((lo_x + 1) / 2 * p.width)) - 1));
  box.y0 = std::min(box.y0, p.y + std::max(0, static_cast<int>(std::floor((lo_y + 1) / 2 * p.height)) - 1));
  box.x1 = std::max(box.x1, p.x + std::min(p.width, static_cast<int>(std::ceil((hi_x + 1) / 2 * p.width)) + 1));
  box.y1 = std::max(box.y1, p.y + std::min(p.height, static_cast<int>(std::ceil((hi_y + 1) / 2 * p.height)) + 1));
}

/// The pixels the transparent parts can touch: the union over views of their boxes'
/// projections, in GL pixels. llvmpipe pays per pixel, so the OIT passes stay inside it.
ScreenBox transparent_screen_box(const std::vector<PreparedView>& views, const std::vector<Surface>& surfaces,
                                 int frame_width, int frame_height) {
  ScreenBox box{frame_width, frame_height, 0, 0};
  for (const PreparedView& p : views) {
    for_each_shown(*p.source, surfaces, [&](const Surface& s) {
      if (s.uploaded && s.min_opacity < kOpaqueFrom) include_projected_box(p, s, box);
    });
  }
  return box;
}

/// Selects `program` and sets its uniforms for surface `s` in view `p`; with a cut, enables
/// the clip distance (the caller disables it after drawing).
void use_program(const OrganProgram& program, const FrameState& frame, const PreparedView& p, const Surface& s,
                 const scene::ClipPlane& clip) {
  glUseProgram(program.id);
  glUniformMatrix4fv(program.loc.view_projection, 1, GL_FALSE, p.view_projection.data());
  glUniform3fv(program.loc.camera_position, 1, p.eye.data());
  glUniform3fv(program.loc.up, 1, p.up.data());
  glUniform3fv(program.loc.light_to_light, std::max(frame.light_count, 1), frame.to_light.data());
  glUniform3fv(program.loc.light_radiance, std::max(frame.light_count, 1), frame.radiance.data());
  glUniform1f(program.loc.specular, s.specular);
  glUniform1f(program.loc.shininess, s.shininess);
  if (!clip.enabled) return;
  const Eigen::Vector3d n = clip.normal.normalized();
  const Eigen::Vector4f plane(static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z()),
                              static_cast<float>(-n.dot(clip.point_m)));
  const Eigen::Vector3f cut = clip.cut_color.cwiseMax(0.0).cwiseMin(1.0).cast<float>();
  glUniform4fv(program.loc.clip_plane, 1, plane.data());
  glUniform3fv(program.loc.cut_color, 1, cut.data());
  glEnable(GL_CLIP_DISTANCE0);
}

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

/// The triangles one surface draws in a view: its vertex array, the index count, and how
/// many of those indices (from the start) are drawn with back faces culled.
struct TriangleRange {
  GLuint vao = 0;
  GLsizei index_count = 0;
  GLsizei culled = 0;
};

TriangleRange triangles_to_draw(const Surface& s, const PreparedView& p, const scene::ClipPlane& clip,
                                bool has_transparent) {
  // The enclosed triangles (set_enclosed) are hidden by the outside when nothing cuts
  // it, every part is opaque and no part of it lies before the near plane (nor the eye
  // inside): then the rest is drawn, in the same order.
  const bool outside_only = s.outside_vao && !clip.enabled && !has_transparent && clear_of_near_plane(s, p);
  TriangleRange range;
  range.vao = outside_only ? s.outside_vao : s.vao;
  range.index_count = outside_only ? s.outside_index_count : s.index_count;
  // Through a cut the inside shows as the cut face; an open surface shows its back:
  // the triangles from two_sided_from on are drawn without culling.
  range.culled = range.index_count;
  if (clip.enabled) {
    range.culled = 0;
  } else if (s.two_sided_from >= 0) {
    const GLsizei before =
        outside_only ? static_cast<GLsizei>(std::lower_bound(s.outside_triangles.begin(), s.outside_triangles.end(),
                                                             s.two_sided_from) -
                                            s.outside_triangles.begin())
                     : s.two_sided_from;
    range.culled = std::min<GLsizei>(3 * before, range.index_count);
  }
  return range;
}

void draw_triangles(const TriangleRange& range) {
  glBindVertexArray(range.vao);
  if (range.culled > 0) glDrawElements(GL_TRIANGLES, range.culled, GL_UNSIGNED_INT, nullptr);
  if (range.culled < range.index_count) {
    glDisable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, range.index_count - range.culled, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<std::uintptr_t>(range.culled) * sizeof(std::uint32_t)));
    glEnable(GL_CULL_FACE);
  }
}

}  // namespace

void Renderer::draw(const scene::Camera& camera, const std::vector<scene::Light>& lights,
                    const scene::Color& background) {
  ViewDraw whole;
  whole.camera = camera;
  draw(std::vector<ViewDraw>{whole}, lights, background);
}

void Renderer::draw(const std::vector<ViewDraw>& views, const std::vector<scene::Light>& lights,
                    const scene::Color& background) {
  Impl& r = *impl_;
  r.prepare_frame(views, lights, background);
  r.make_current();
  r.opaque_pass();
  r.frame_resolved = false;
  if (!r.frame.transparent_box.empty()) {
    r.transparent_pass();
    r.composite_pass();
  }
  glBindVertexArray(0);
  glFinish();
  check_gl("draw");
}

void Renderer::Impl::prepare_frame(const std::vector<ViewDraw>& views, const std::vector<scene::Light>& lights,
                                   const scene::Color& background) {
  if (lights.size() > static_cast<std::size_t>(kMaxLights)) {
    throw Error(ExitCode::kDataError, "render: at most " + std::to_string(kMaxLights) +
                                          " lights are supported, the scene has " +
                                          std::to_string(lights.size()));
  }
  frame.views.clear();
  for (const ViewDraw& v : views) frame.views.push_back(prepare_view(v, width, height, surfaces));
  pack_lights(lights, frame);
  frame.background = background;
  frame.transparent_box = transparent_screen_box(frame.views, surfaces, width, height);
}

void Renderer::Impl::opaque_pass() {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo());
  glViewport(0, 0, width, height);
  // The framebuffer holds sRGB-encoded values (the shader encodes), so the background
  // is cleared as given.
  glClearColor(static_cast<float>(frame.background.x()), static_cast<float>(frame.background.y()),
               static_cast<float>(frame.background.z()), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (const PreparedView& p : frame.views) draw_view(p, false);
}

void Renderer::Impl::transparent_pass() {
  // Weighted blended OIT: accumulate every transparent part against the opaque depth
  // (tested, not written); composite_pass blends the result over the opaque frame.
  if (!oit.fbo) oit.create(width, height, samples, samples > 0 ? multisampled.depth : resolved.depth);
  const ScreenBox& box = frame.transparent_box;
  glBindFramebuffer(GL_FRAMEBUFFER, oit.fbo);
  glViewport(0, 0, width, height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
  const float zero[] = {0, 0, 0, 0};
  const float one[] = {1, 1, 1, 1};
  glClearBufferfv(GL_COLOR, 0, zero);
  glClearBufferfv(GL_COLOR, 1, one);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunci(0, GL_ONE, GL_ONE);
  glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
  for (const PreparedView& p : frame.views) draw_view(p, true);
  glDepthMask(GL_TRUE);
  glDisable(GL_SCISSOR_TEST);  // Blits are scissored too: the opaque resolve needs every pixel.
}

void Renderer::Impl::composite_pass() {
  if (samples > 0) {  // Resolve the opaque frame and both OIT targets, then composite.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled.fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved.fbo);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, oit.fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, oit.texture_fbo);
    for (const GLenum attachment : {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1}) {
      glReadBuffer(attachment);
      glDrawBuffer(attachment);
      glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glDrawBuffers(2, both);
    frame_resolved = true;
  }
  // The transparent pass left blending on; the scissor is the transparent box again.
  glBindFramebuffer(GL_FRAMEBUFFER, resolved.fbo);
  glEnable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glUseProgram(oit.composite_program);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, oit.accumulation);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, oit.revealage);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(oit.empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo());
}

void Renderer::Impl::draw_view(const PreparedView& p, bool transparent_pass) {
  glViewport(p.x, p.y, p.width, p.height);
  for_each_shown(*p.source, surfaces, [&](const Surface& s) { draw_surface(p, s, transparent_pass); });
}

void Renderer::Impl::draw_surface(const PreparedView& p, const Surface& s, bool transparent_pass) {
  if (!s.uploaded) return;
  const bool has_transparent = s.min_opacity < kOpaqueFrom;
  if (transparent_pass ? !has_transparent : s.max_opacity < kOpaqueFrom) return;
  const scene::ClipPlane& clip = s.clip.enabled ? s.clip : p.source->clip;
  int variant = clip.enabled ? kClipVariant : 0;
  if (transparent_pass) variant |= kTransparentPartVariant;
  else if (has_transparent) variant |= kOpaquePartVariant;
  use_program(program(frame.light_count, variant), frame, p, s, clip);
  draw_triangles(triangles_to_draw(s, p, clip, has_transparent));
  if (clip.enabled) glDisable(GL_CLIP_DISTANCE0);
}

}  // namespace systole::render
