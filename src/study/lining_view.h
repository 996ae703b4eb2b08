#pragma once
// What a view from outside shows of a generated anatomy's linings: the scene's views (their
// cameras moving as the clip's do, at the scene's output size), uncut and opaque, every
// organ coloured by region, drawn twice with the cavities' linings in two colours; the pixels
// that differ are linings seen. Every lining is drawn: the renderer's leaving out what the
// heart's closed outside hides (render::Renderer::set_enclosed) assumes what this checks.
// No anti-aliasing, so a pixel is a lining's or not.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "common/image.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "world/world.h"

namespace systole::study {

class LiningView {
 public:
  /// The views of `scene` over the organs `world` built from it, their cameras placed as a
  /// clip places them (clip::with_cameras_placed).
  LiningView(const scene::Scene& scene, const world::World& world);

  /// No organ has a generated anatomy: nothing to look at.
  bool empty() const { return lining_vertices_ == 0; }

  /// Draws clip frame `frame` with organ o at positions[o] (unit: m); returns how many pixels
  /// show a lining.
  int lining_pixels(const std::vector<Eigen::Matrix3Xd>& positions, int frame);

  int width() const { return width_; }    ///< unit: px
  int height() const { return height_; }  ///< unit: px
  int frames() const { return frames_; }  ///< Frames drawn.
  int frames_with_pixels() const { return frames_with_pixels_; }
  int worst_pixels() const { return worst_pixels_; }  ///< The most lining pixels in one frame.
  int worst_frame() const { return worst_frame_; }    ///< Its frame; -1: none seen.

 private:
  /// Uploads every organ's linings in colour `which` (0 or 1), draws, reads into `out`.
  void draw(int which, Image& out);

  const scene::Scene scene_;
  int width_ = 0, height_ = 0;
  std::unique_ptr<render::Renderer> renderer_;
  std::vector<int> ids_;                              ///< Per organ: its surface.
  std::vector<std::vector<Eigen::Vector3i>> drawn_;   ///< Per organ: the triangles drawn.
  std::vector<std::vector<float>> colors_[2];         ///< Per organ: sRGB per vertex, linings in colour 0 or 1.
  std::vector<render::ViewDraw> views_;
  std::vector<float> positions_, normals_;            ///< Scratch: one organ's upload.
  Image images_[2];
  int lining_vertices_ = 0;
  int frames_ = 0, frames_with_pixels_ = 0, worst_pixels_ = 0, worst_frame_ = -1;
};

}  // namespace systole::study
