// The 3D teaching visuals in the renderer: order-independent transparency, clip planes,
// per-frame colours, split-screen views, and the colour maps behind the colour bars.

#include <gtest/gtest.h>

#include <cstdlib>

#include "common/error.h"
#include "render/color_map.h"
#include "render/renderer.h"
#include "render/test_shapes.h"

namespace systole::render {
namespace {

using testing::Shape;
using testing::uv_sphere;

constexpr int kWidth = 160;
constexpr int kHeight = 120;
const scene::Color kBackground(0.06, 0.07, 0.09);
const scene::Color kRed(0.85, 0.1, 0.1);
const scene::Color kWhite(0.95, 0.95, 0.95);
const scene::Color kBlue(0.1, 0.2, 0.9);

scene::Camera front_camera() {
  scene::Camera camera;
  camera.position_m = Eigen::Vector3d(0, 0, 3);
  return camera;
}

std::vector<scene::Light> front_light() {
  scene::Light light;
  light.direction = Eigen::Vector3d(0, 0, -1);
  return {light};
}

int add(Renderer& renderer, const Shape& shape, const scene::Color& color, double opacity = 1) {
  scene::Material material;
  material.opacity = opacity;
  material.specular = 0;  // No highlight: the centre pixel shows the colours, not the light.
  const int id = renderer.add_surface(shape.triangles, std::vector<scene::Color>(shape.vertex_count(), color), material);
  renderer.update_surface(id, shape.positions.data(), shape.normals.data());
  return id;
}

Image render(Renderer& renderer, const std::vector<ViewDraw>& views) {
  renderer.draw(views, front_light(), kBackground);
  Image image;
  renderer.read_frame(image);
  return image;
}

Image render(Renderer& renderer) {
  ViewDraw whole;
  whole.camera = front_camera();
  return render(renderer, {whole});
}

std::array<int, 3> rgb(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

bool is_background(const Image& image, int x, int y) {
  const auto p = rgb(image, x, y);
  return std::abs(p[0] - 15) <= 1 && std::abs(p[1] - 18) <= 1 && std::abs(p[2] - 23) <= 1;
}

/// A red sphere inside a white one of the given opacity, seen from the front.
Image nested_spheres(double outer_opacity, int msaa) {
  Renderer renderer(kWidth, kHeight, msaa);
  add(renderer, uv_sphere(Eigen::Vector3f::Zero(), 0.3f, 24, 32), kRed);
  add(renderer, uv_sphere(Eigen::Vector3f::Zero(), 0.6f, 24, 32), kWhite, outer_opacity);
  return render(renderer);
}

TEST(Transparency, InnerOrganShowsThroughAHalfOpaqueOuterOne) {
  for (const int msaa : {0, 4}) {
    const auto centre = rgb(nested_spheres(0.5, msaa), kWidth / 2, kHeight / 2);
    EXPECT_GT(centre[0], centre[1] + 40) << "pinkish: the red shows through, msaa " << msaa;
    EXPECT_GT(centre[1], 60) << "and the white veil lightens it, msaa " << msaa;
  }
}

TEST(Transparency, FullOpacityHidesTheInnerOrgan) {
  const auto centre = rgb(nested_spheres(1.0, 0), kWidth / 2, kHeight / 2);
  EXPECT_LT(std::abs(centre[0] - centre[1]), 8) << "white, not pink";
  EXPECT_GT(centre[1], 150);
}

TEST(Transparency, ZeroOpacityShowsTheInnerOrganAlone) {
  Renderer renderer(kWidth, kHeight, 0);
  add(renderer, uv_sphere(Eigen::Vector3f::Zero(), 0.3f, 24, 32), kRed);
  const auto alone = rgb(render(renderer), kWidth / 2, kHeight / 2);
  const auto veiled = rgb(nested_spheres(0.0, 0), kWidth / 2, kHeight / 2);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(veiled[k], alone[k], 1) << k;
}

TEST(Transparency, TransparentOverBackgroundBlendsWithIt) {
  Renderer renderer(kWidth, kHeight, 0);
  add(renderer, uv_sphere(Eigen::Vector3f::Zero(), 0.6f, 24, 32), kWhite, 0.5);
  const Image image = render(renderer);
  const auto centre = rgb(image, kWidth / 2, kHeight / 2);
  EXPECT_GT(centre[0], 60);
  EXPECT_LT(centre[0], 200);  // Neither background nor opaque white.
  EXPECT_TRUE(is_background(image, 2, 2));
}

scene::ClipPlane clip(const Eigen::Vector3d& normal) {
  scene::ClipPlane c;
  c.enabled = true;
  c.normal = normal;
  c.cut_color = scene::Color(0.2, 0.9, 0.3);  // Green: unlike the red organ.
  return c;
}

TEST(ClipPlane, RemovesOneSideAndShowsTheCutColourInside) {
  const Shape sphere = uv_sphere(Eigen::Vector3f::Zero(), 0.6f, 32, 48);
  Renderer renderer(kWidth, kHeight, 0);
  const int id = add(renderer, sphere, kRed);
  const Image whole = render(renderer);
  const int left = kWidth / 2 - 25, right = kWidth / 2 + 25;
  ASSERT_FALSE(is_background(whole, left, kHeight / 2));

  // Keep x >= 0: the left half is gone; through the opening the inside is the cut colour.
  renderer.set_clip(id, clip(Eigen::Vector3d::UnitX()));
  const Image cut = render(renderer);
  EXPECT_TRUE(is_background(cut, left, kHeight / 2));
  EXPECT_EQ(rgb(cut, right, kHeight / 2), rgb(whole, right, kHeight / 2)) << "the kept side is unchanged";

  // Keep the back half (z <= 0): looking in, the inner wall faces the eye, in the cut colour.
  renderer.set_clip(id, clip(-Eigen::Vector3d::UnitZ()));
  const auto inside = rgb(render(renderer), kWidth / 2, kHeight / 2);
  EXPECT_NEAR(inside[0], 0.2 * 255, 3);
  EXPECT_NEAR(inside[1], 0.9 * 255, 3);
  EXPECT_NEAR(inside[2], 0.3 * 255, 3);

  // Switched off, the surface is whole again.
  renderer.set_clip(id, scene::ClipPlane{});
  EXPECT_EQ(render(renderer).rgb, whole.rgb);
}

TEST(ClipPlane, AViewsClipCutsOnlyThatView) {
  Renderer renderer(kWidth, kHeight, 0);
  add(renderer, uv_sphere(Eigen::Vector3f::Zero(), 0.6f, 32, 48), kRed);
  ViewDraw plain, cut;
  plain.camera = cut.camera = front_camera();
  plain.rect = {0, 0, kWidth / 2, kHeight};
  cut.rect = {kWidth / 2, 0, kWidth / 2, kHeight};
  cut.clip = clip(-Eigen::Vector3d::UnitZ());
  const Image image = render(renderer, {plain, cut});
  const auto outside = rgb(image, kWidth / 4, kHeight / 2);
  const auto inside = rgb(image, 3 * kWidth / 4, kHeight / 2);
  EXPECT_GT(outside[0], outside[1] + 40);
  EXPECT_GT(inside[1], inside[0] + 40);
}

TEST(Views, EachViewDrawsItsSurfacesInItsRectangle) {
  Renderer renderer(kWidth, kHeight, 0);
  const int red = add(renderer, uv_sphere(Eigen::Vector3f::Zero(), 0.5f, 24, 32), kRed);
  const int blue = add(renderer, uv_sphere(Eigen::Vector3f::Zero(), 0.5f, 24, 32), kBlue);
  ViewDraw left, right;
  left.camera = right.camera = front_camera();
  left.rect = {0, 0, kWidth / 2, kHeight};
  left.surfaces = {red};
  right.rect = {kWidth / 2, 0, kWidth / 2, kHeight};
  right.surfaces = {blue};
  const Image image = render(renderer, {left, right});
  const auto l = rgb(image, kWidth / 4, kHeight / 2);
  const auto r = rgb(image, 3 * kWidth / 4, kHeight / 2);
  EXPECT_GT(l[0], l[2] + 40) << "red on the left";
  EXPECT_GT(r[2], r[0] + 40) << "blue on the right";
  // The sphere is centred in each half (its own aspect), and nothing crosses the border.
  EXPECT_TRUE(is_background(image, kWidth / 2 - 1, 2));
  EXPECT_TRUE(is_background(image, kWidth / 2, 2));
  // A view below the other: top-left origin.
  ViewDraw top = left, bottom = right;
  top.rect = {0, 0, kWidth, kHeight / 2};
  bottom.rect = {0, kHeight / 2, kWidth, kHeight / 2};
  const Image stacked = render(renderer, {top, bottom});
  EXPECT_GT(rgb(stacked, kWidth / 2, kHeight / 4)[0], rgb(stacked, kWidth / 2, kHeight / 4)[2] + 40);
  EXPECT_GT(rgb(stacked, kWidth / 2, 3 * kHeight / 4)[2], rgb(stacked, kWidth / 2, 3 * kHeight / 4)[0] + 40);
}

TEST(Views, RejectsRectanglesOutsideTheFrameAndUnknownSurfaces) {
  Renderer renderer(kWidth, kHeight, 0);
  ViewDraw v;
  v.camera = front_camera();
  v.rect = {kWidth / 2, 0, kWidth, kHeight};
  EXPECT_THROW(renderer.draw({v}, front_light(), kBackground), Error);
  v.rect = {};
  v.surfaces = {3};
  EXPECT_THROW(renderer.draw({v}, front_light(), kBackground), Error);
}

TEST(Colors, UpdateColorsRecoloursTheSurface) {
  Renderer renderer(kWidth, kHeight, 0);
  const Shape sphere = uv_sphere(Eigen::Vector3f::Zero(), 0.5f, 24, 32);
  const int id = add(renderer, sphere, kRed);
  std::vector<float> blue;
  for (int v = 0; v < sphere.vertex_count(); ++v) blue.insert(blue.end(), {0.1f, 0.2f, 0.9f});
  renderer.update_colors(id, blue.data());
  const auto centre = rgb(render(renderer), kWidth / 2, kHeight / 2);
  EXPECT_GT(centre[2], centre[0] + 40);
  EXPECT_THROW(renderer.update_colors(id + 1, blue.data()), Error);
}

TEST(ColorMap, DivergingEndsAndMiddle) {
  const ColorMap map{ColorMapKind::kDiverging, -0.1, 0.1, "strain", "shortened", "stretched"};
  const scene::Color low = map.at(-0.1), mid = map.at(0), high = map.at(0.1);
  EXPECT_GT(low.z(), low.x() + 0.3) << "shortened is blue";
  EXPECT_GT(high.x(), high.z() + 0.3) << "stretched is red";
  EXPECT_NEAR(mid.x(), mid.z(), 1e-12) << "rest is grey";
  EXPECT_EQ(map.at(-5), low) << "clamped";
  EXPECT_EQ(map.at(5), high);
  // Monotone towards blue as the value falls.
  EXPECT_GT(map.at(-0.05).z() - map.at(-0.05).x(), map.at(-0.01).z() - map.at(-0.01).x());
}

TEST(ColorMap, OrganMapsAndLegends) {
  scene::Organ organ;
  organ.regions.resize(9);
  for (std::size_t r = 0; r < organ.regions.size(); ++r) organ.regions[r].name = std::string(1, static_cast<char>('a' + r));
  organ.regions[1].has_color = true;
  organ.regions[1].color = scene::Color(0.1, 0.2, 0.3);
  EXPECT_FALSE(organ_color_map(organ).has);
  EXPECT_EQ(region_legend(organ).size(), 1u) << "material: the regions with a colour";
  organ.color_by = scene::ColorBy::kRegion;
  const auto legend = region_legend(organ);
  ASSERT_EQ(legend.size(), 9u);
  EXPECT_EQ(legend[1].color, scene::Color(0.1, 0.2, 0.3));
  EXPECT_NE(legend[0].color, legend[2].color);
  organ.color_by = scene::ColorBy::kActivation;
  organ.color_range = Eigen::Vector2d(0, 1);
  const OrganColorMap m = organ_color_map(organ);
  ASSERT_TRUE(m.has);
  EXPECT_EQ(m.map.kind, ColorMapKind::kSequential);
  EXPECT_GT(m.map.at(1).sum(), m.map.at(0).sum()) << "contracted is brighter";
  EXPECT_TRUE(region_legend(organ).empty());
}

// A hollow ball as a heart is built: a lining (facing into the cavity, blue) listed first,
// the red outside, then open pieces drawn two-sided: a leaflet inside the cavity and one
// outside facing away from the eye (seen only from behind).
struct HollowBall {
  Shape shape;
  std::vector<scene::Color> colors;
  std::vector<char> enclosed;  ///< The lining and the inner leaflet.
  int two_sided_from = 0;
};

HollowBall hollow_ball() {
  HollowBall b;
  const auto append = [&b](Shape piece, const scene::Color& color, bool enclosed, bool reverse) {
    const int first = b.shape.vertex_count();
    for (Eigen::Vector3i t : piece.triangles) {
      if (reverse) std::swap(t[1], t[2]);
      b.shape.triangles.push_back(t + Eigen::Vector3i::Constant(first));
      b.enclosed.push_back(enclosed);
    }
    if (reverse) {
      for (float& n : piece.normals) n = -n;
    }
    b.shape.positions.insert(b.shape.positions.end(), piece.positions.begin(), piece.positions.end());
    b.shape.normals.insert(b.shape.normals.end(), piece.normals.begin(), piece.normals.end());
    b.colors.insert(b.colors.end(), static_cast<std::size_t>(piece.vertex_count()), color);
  };
  append(uv_sphere(Eigen::Vector3f::Zero(), 0.45f, 24, 32), kBlue, true, true);
  append(uv_sphere(Eigen::Vector3f::Zero(), 0.6f, 24, 32), kRed, false, false);
  b.two_sided_from = static_cast<int>(b.shape.triangles.size());
  append(testing::triangle(0.2f, 0.1f), kWhite, true, false);
  Shape away = testing::triangle(0.15f, 0.7f);  // In front of the ball, its back to the eye.
  away.translate(Eigen::Vector3f(0.3f, 0.2f, 0));
  append(away, scene::Color(0.2, 0.9, 0.3), false, true);
  return b;
}

/// The hollow ball drawn in `views`, with its enclosed triangles marked or not.
Image draw_hollow_ball(const std::vector<ViewDraw>& views, bool mark, double opacity = 1,
                       const scene::ClipPlane& own_clip = {}, const std::vector<char>* marks = nullptr) {
  const HollowBall b = hollow_ball();
  Renderer renderer(kWidth, kHeight, 0);
  scene::Material material;
  material.opacity = opacity;
  const int id = renderer.add_surface(b.shape.triangles, b.colors, material);
  renderer.set_two_sided(id, b.two_sided_from);
  renderer.set_clip(id, own_clip);
  if (mark) renderer.set_enclosed(id, marks ? *marks : b.enclosed);
  renderer.update_surface(id, b.shape.positions.data(), b.shape.normals.data());
  return render(renderer, views);
}

ViewDraw whole_view(const Eigen::Vector3d& eye = Eigen::Vector3d(0, 0, 3)) {
  ViewDraw v;
  v.camera = front_camera();
  v.camera.position_m = eye;
  return v;
}

TEST(Enclosed, AnOutsideViewLeavesThemOutWithTheSamePixels) {
  const Image all = draw_hollow_ball({whole_view()}, false);
  EXPECT_EQ(draw_hollow_ball({whole_view()}, true).rgb, all.rgb);
  // The leaflet outside (green), seen from behind, is still drawn two-sided among the rest.
  int green = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const auto p = rgb(all, x, y);
      green += p[1] > p[0] + 40 && p[1] > p[2] + 40;
    }
  }
  EXPECT_GT(green, 20);
  const HollowBall b = hollow_ball();
  // What is left out is left out: mark the outside instead, and the lining shows.
  std::vector<char> outside(b.enclosed.size());
  for (std::size_t t = 0; t < outside.size(); ++t) outside[t] = !b.enclosed[t];
  const Image lining_only = draw_hollow_ball({whole_view()}, true, 1, {}, &outside);
  const auto near_centre = rgb(lining_only, kWidth / 2 - 12, kHeight / 2 + 8);  // Off the highlight.
  EXPECT_GT(near_centre[2], near_centre[0] + 40) << "blue: the lining, drawn without the outside";
}

TEST(Enclosed, ViewsThatCutSeeThroughOrComeInsideDrawThemAsBefore) {
  ViewDraw cut = whole_view();
  cut.clip = clip(-Eigen::Vector3d::UnitZ());
  const Image cut_all = draw_hollow_ball({cut}, false);
  EXPECT_EQ(draw_hollow_ball({cut}, true).rgb, cut_all.rgb) << "the view's cut";
  const auto lining = rgb(cut_all, kWidth / 2, kHeight / 2);
  EXPECT_GT(lining[2], lining[0] + 40) << "through the cut, the lining";

  EXPECT_EQ(draw_hollow_ball({whole_view()}, true, 1, clip(-Eigen::Vector3d::UnitZ())).rgb,
            draw_hollow_ball({whole_view()}, false, 1, clip(-Eigen::Vector3d::UnitZ())).rgb)
      << "the surface's own cut";
  EXPECT_EQ(draw_hollow_ball({whole_view()}, true, 0.5).rgb, draw_hollow_ball({whole_view()}, false, 0.5).rgb)
      << "see-through";
  const ViewDraw inside = whole_view(Eigen::Vector3d(0, 0, 0.3));
  const Image from_inside = draw_hollow_ball({inside}, false);
  EXPECT_EQ(draw_hollow_ball({inside}, true).rgb, from_inside.rgb) << "the eye inside";
  const auto seen = rgb(from_inside, kWidth / 2, kHeight / 2);
  EXPECT_GT(seen[0] + seen[1] + seen[2], 100) << "from inside, the lining and leaflet";

  // Split screen: the plain view leaves them out, the cut one draws them; the same pixels.
  ViewDraw left = whole_view(), right = cut;
  left.rect = {0, 0, kWidth / 2, kHeight};
  right.rect = {kWidth / 2, 0, kWidth / 2, kHeight};
  EXPECT_EQ(draw_hollow_ball({left, right}, true).rgb, draw_hollow_ball({left, right}, false).rgb);
}

TEST(Enclosed, RejectsAFlagCountThatIsNotTheTriangleCount) {
  const HollowBall b = hollow_ball();
  Renderer renderer(kWidth, kHeight, 0);
  const int id = renderer.add_surface(b.shape.triangles, b.colors, scene::Material{});
  EXPECT_THROW(renderer.set_enclosed(id, std::vector<char>(3, 0)), Error);
  EXPECT_THROW(renderer.set_enclosed(id + 1, b.enclosed), Error);
}

}  // namespace
}  // namespace systole::render
