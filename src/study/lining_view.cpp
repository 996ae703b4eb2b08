#include "study/lining_view.h"

#include "clip/camera_framing.h"
#include "clip/render_clip.h"
#include "clip/render_detail.h"
#include "mesh/anatomy.h"
#include "mesh/normals.h"
#include "render/color_map.h"

namespace systole::study {
namespace {

/// The two colours a lining is drawn in, as far apart as sRGB allows in every channel.
const scene::Color kLiningColor[2] = {scene::Color(0, 1, 0), scene::Color(1, 0, 1)};

}  // namespace

LiningView::LiningView(const scene::Scene& given, const world::World& world)
    : scene_(clip::with_cameras_placed(given, world)), width_(given.output.width), height_(given.output.height) {
  const scene::Scene& scene = scene_;
  for (const auto& body : world.organs) lining_vertices_ += static_cast<int>(mesh::lining_vertices(body.geometry.mesh.anatomy).size());
  if (empty()) return;
  renderer_ = std::make_unique<render::Renderer>(width_, height_, 0);
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& body = world.organs[o];
    scene::Organ organ = scene.organs[o];
    organ.color_by = scene::ColorBy::kRegion;
    const std::vector<scene::Color> colors = render::static_vertex_colors(organ, body.geometry.vertex_region);
    for (int which = 0; which < 2; ++which) {
      std::vector<scene::Color> c = colors;
      for (const mesh::Cavity& cavity : body.geometry.mesh.anatomy.cavities) {
        for (const Eigen::Vector3i& t : cavity.lining) {
          for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(t[k])] = kLiningColor[which];
        }
      }
      std::vector<float>& flat = colors_[which].emplace_back();
      for (const scene::Color& v : c) flat.insert(flat.end(), {float(v[0]), float(v[1]), float(v[2])});
    }
    clip::RenderDetail detail = clip::render_detail(scene, world, o);
    scene::Material opaque = organ.material;
    opaque.opacity = 1;
    ids_.push_back(renderer_->add_surface(detail.triangles, colors, opaque));
    renderer_->set_two_sided(ids_.back(), body.geometry.report.closed() ? -1 : detail.two_sided_from);
    drawn_.push_back(std::move(detail.triangles));
  }
  views_ = clip::frame_views(scene, ids_);
  for (render::ViewDraw& view : views_) view.clip = scene::ClipPlane{};  // Uncut.
}

void LiningView::draw(int which, Image& out) {
  for (std::size_t o = 0; o < ids_.size(); ++o) renderer_->update_colors(ids_[o], colors_[which][o].data());
  renderer_->draw(views_, scene_.lights, scene_.output.background);
  renderer_->read_frame(out);
}

int LiningView::lining_pixels(const std::vector<Eigen::Matrix3Xd>& positions, int frame) {
  if (empty()) return 0;
  for (std::size_t o = 0; o < ids_.size(); ++o) {
    const Eigen::Matrix3Xd& x = positions[o];
    positions_.assign(x.data(), x.data() + x.size());
    normals_.resize(positions_.size());
    mesh::vertex_normals(x.data(), static_cast<int>(x.cols()), drawn_[o], normals_.data());
    renderer_->update_surface(ids_[o], positions_.data(), normals_.data());
  }
  clip::set_view_cameras(scene_, frame / scene_.output.fps, views_);
  draw(0, images_[0]);
  draw(1, images_[1]);
  int pixels = 0;
  for (std::size_t i = 0; i < images_[0].rgb.size(); i += 3) {
    pixels += images_[0].rgb[i] != images_[1].rgb[i] || images_[0].rgb[i + 1] != images_[1].rgb[i + 1] ||
              images_[0].rgb[i + 2] != images_[1].rgb[i + 2];
  }
  ++frames_;
  if (pixels > 0) ++frames_with_pixels_;
  if (pixels > worst_pixels_) worst_pixels_ = pixels, worst_frame_ = frame;
  return pixels;
}

}  // namespace systole::study
