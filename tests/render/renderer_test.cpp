#include "render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "common/error.h"
#include "render/test_shapes.h"

namespace systole::render {
namespace {

using testing::Shape;
using testing::triangle;
using testing::uv_sphere;

constexpr int kWidth = 160;
constexpr int kHeight = 120;
const scene::Color kBackground(0.06, 0.07, 0.09);
const scene::Color kOrgan(0.72, 0.16, 0.14);

scene::Camera camera_at(double z) {
  scene::Camera camera;
  camera.position_m = Eigen::Vector3d(0, 0, z);
  camera.target_m = Eigen::Vector3d::Zero();
  return camera;
}

std::vector<scene::Light> front_light() {
  scene::Light light;
  light.direction = Eigen::Vector3d(0, 0, -1);
  return {light};
}

std::vector<scene::Color> colors(const Shape& shape, const scene::Color& c) {
  return std::vector<scene::Color>(static_cast<std::size_t>(shape.vertex_count()), c);
}

int add(Renderer& renderer, const Shape& shape, const std::vector<scene::Color>& vertex_colors) {
  const int id = renderer.add_surface(shape.triangles, vertex_colors, scene::Material{});
  renderer.update_surface(id, shape.positions.data(), shape.normals.data());
  return id;
}

Image render(Renderer& renderer, const scene::Camera& camera,
             const std::vector<scene::Light>& lights = front_light()) {
  renderer.draw(camera, lights, kBackground);
  Image image;
  renderer.read_frame(image);
  return image;
}

/// The 8-bit value glClearColor's float becomes (round to nearest).
std::array<int, 3> expected_background() {
  return {static_cast<int>(std::lround(kBackground.x() * 255)),
          static_cast<int>(std::lround(kBackground.y() * 255)),
          static_cast<int>(std::lround(kBackground.z() * 255))};
}

bool is_background(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  const auto bg = expected_background();
  return p[0] == bg[0] && p[1] == bg[1] && p[2] == bg[2];
}

int covered_pixels(const Image& image) {
  int count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) count += !is_background(image, x, y);
  }
  return count;
}

int luminance(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return p[0] + p[1] + p[2];
}

TEST(TestShapes, SphereIsOutwardCounterClockwise) {
  const Shape s = uv_sphere(Eigen::Vector3f(1, 2, 3), 0.5f, 12, 16);
  for (const Eigen::Vector3i& t : s.triangles) {
    const Eigen::Vector3f a = s.position(t[0]), b = s.position(t[1]), c = s.position(t[2]);
    const Eigen::Vector3f centroid = (a + b + c) / 3 - Eigen::Vector3f(1, 2, 3);
    EXPECT_GT((b - a).cross(c - a).dot(centroid), 0);
  }
}

TEST(Renderer, InfoNamesMesa) {
  Renderer renderer(16, 16, 0);
  const GlInfo info = renderer.info();
  EXPECT_TRUE(info.renderer.find("llvmpipe") != std::string::npos ||
              info.version.find("Mesa") != std::string::npos)
      << info.renderer << " / " << info.version;
  EXPECT_FALSE(info.glsl_version.empty());
}

TEST(Renderer, RejectsBadArguments) {
  EXPECT_THROW(Renderer(0, 10, 0), Error);
  EXPECT_THROW(Renderer(10, 10, 3), Error);
  EXPECT_THROW(Renderer(10, 10, 8), Error);
  Renderer renderer(16, 16, 0);
  const Shape tri = triangle(0.5f, 0);
  std::vector<Eigen::Vector3i> bad = {Eigen::Vector3i(0, 1, 3)};
  EXPECT_THROW(renderer.add_surface(bad, colors(tri, kOrgan), {}), Error);
  EXPECT_THROW(renderer.update_surface(7, tri.positions.data(), tri.normals.data()), Error);
  const int id = renderer.add_surface(tri.triangles, colors(tri, kOrgan), {});
  std::vector<float> nan_positions = tri.positions;
  nan_positions[4] = std::nanf("");
  EXPECT_THROW(renderer.update_surface(id, nan_positions.data(), tri.normals.data()), Error);
  EXPECT_THROW(renderer.draw(camera_at(0), front_light(), kBackground), Error);  // Eye at target.
  EXPECT_THROW(renderer.draw(camera_at(2), std::vector<scene::Light>(kMaxLights + 1), kBackground),
               Error);
}

TEST(Renderer, EmptySceneIsBackground) {
  Renderer renderer(kWidth, kHeight, 4);
  const Image image = render(renderer, camera_at(3));
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  EXPECT_EQ(covered_pixels(image), 0);
}

TEST(Renderer, SphereCoversCentreNotCorners) {
  Renderer renderer(kWidth, kHeight, 4);
  const Shape sphere = uv_sphere(Eigen::Vector3f::Zero(), 0.5f, 24, 32);
  add(renderer, sphere, colors(sphere, kOrgan));
  const Image image = render(renderer, camera_at(3));
  EXPECT_FALSE(is_background(image, kWidth / 2, kHeight / 2));
  const std::uint8_t* centre = image.pixel(kWidth / 2, kHeight / 2);
  EXPECT_GT(centre[0], centre[1] + 40) << "organ red expected";
  EXPECT_GT(centre[0], centre[2] + 40);
  for (const auto& [x, y] : {std::pair{0, 0}, {kWidth - 1, 0}, {0, kHeight - 1}, {kWidth - 1, kHeight - 1}}) {
    EXPECT_TRUE(is_background(image, x, y)) << x << "," << y;
  }
}

TEST(Renderer, ImageIsNotUpsideDown) {
  Renderer renderer(kWidth, kHeight, 0);
  const Shape sphere = uv_sphere(Eigen::Vector3f(0, 0.6f, 0), 0.3f, 16, 24);
  add(renderer, sphere, colors(sphere, kOrgan));
  const Image image = render(renderer, camera_at(3));
  int top = 0, bottom = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) (y < kHeight / 2 ? top : bottom) += !is_background(image, x, y);
  }
  EXPECT_GT(top, 100);
  EXPECT_EQ(bottom, 0);
}

TEST(Renderer, FartherCameraCoversFewerPixels) {
  Renderer renderer(kWidth, kHeight, 0);
  const Shape sphere = uv_sphere(Eigen::Vector3f::Zero(), 0.5f, 24, 32);
  add(renderer, sphere, colors(sphere, kOrgan));
  const int near_count = covered_pixels(render(renderer, camera_at(2.5)));
  const int far_count = covered_pixels(render(renderer, camera_at(5)));
  EXPECT_GT(far_count, 0);
  // Projected area falls with distance squared (roughly; the silhouette grows a little).
  EXPECT_LT(far_count * 3, near_count);
}

TEST(Renderer, PerVertexColoursShow) {
  Renderer renderer(kWidth, kHeight, 4);
  const Shape sphere = uv_sphere(Eigen::Vector3f::Zero(), 0.5f, 24, 32);
  std::vector<scene::Color> vertex_colors;
  for (int v = 0; v < sphere.vertex_count(); ++v) {
    vertex_colors.push_back(sphere.position(v).y() > 0 ? scene::Color(0.8, 0.1, 0.1)
                                                        : scene::Color(0.1, 0.2, 0.8));
  }
  add(renderer, sphere, vertex_colors);
  const Image image = render(renderer, camera_at(3));
  const std::uint8_t* upper = image.pixel(kWidth / 2, kHeight / 2 - 15);
  const std::uint8_t* lower = image.pixel(kWidth / 2, kHeight / 2 + 15);
  EXPECT_GT(upper[0], upper[2] + 60);
  EXPECT_GT(lower[2], lower[0] + 60);
}

TEST(Renderer, BackFacesAreCulled) {
  Renderer renderer(kWidth, kHeight, 0);
  const Shape tri = triangle(0.5f, 0);
  add(renderer, tri, colors(tri, kOrgan));
  EXPECT_GT(covered_pixels(render(renderer, camera_at(2))), 500);
  EXPECT_EQ(covered_pixels(render(renderer, camera_at(-2))), 0);
}

TEST(Renderer, ATwoSidedSurfaceSeenFromBehindIsLitAsTheSideTheEyeSees) {
  Renderer renderer(kWidth, kHeight, 0);
  const Shape tri = triangle(0.5f, 0);
  const int id = add(renderer, tri, colors(tri, kOrgan));
  renderer.set_two_sided(id, 0);
  const Image front = render(renderer, camera_at(2));
  scene::Light from_behind;
  from_behind.direction = Eigen::Vector3d(0, 0, 1);  // Travels towards +z: lights the back.
  const Image back = render(renderer, camera_at(-2), {from_behind});
  EXPECT_GT(covered_pixels(back), 500) << "an open triangle seen from behind is drawn";
  EXPECT_EQ(covered_pixels(back), covered_pixels(front)) << "mirror images cover as much";
  EXPECT_GT(luminance(back, kWidth / 2, kHeight / 2 + 5), luminance(front, kWidth / 2, kHeight / 2 + 5) / 2)
      << "lit from the eye's side, not dark as a back face";
}

TEST(Renderer, LitSideIsBrighter) {
  Renderer renderer(kWidth, kHeight, 4);
  const Shape sphere = uv_sphere(Eigen::Vector3f::Zero(), 0.5f, 24, 32);
  add(renderer, sphere, colors(sphere, kOrgan));
  scene::Light light;
  light.direction = Eigen::Vector3d(1, 0, -0.3);  // Travels left to right: lights the left side.
  const Image image = render(renderer, camera_at(3), {light});
  const int radius_px = 18;  // The sphere's radius is about 28 px here.
  const int left = luminance(image, kWidth / 2 - radius_px, kHeight / 2);
  const int right = luminance(image, kWidth / 2 + radius_px, kHeight / 2);
  EXPECT_GT(left, right + 60) << left << " vs " << right;
  EXPECT_FALSE(is_background(image, kWidth / 2 + radius_px, kHeight / 2));  // Ambient and rim.
}

TEST(Renderer, UpdateSurfaceMovesTheObject) {
  Renderer renderer(kWidth, kHeight, 0);
  Shape sphere = uv_sphere(Eigen::Vector3f(-0.6f, 0, 0), 0.3f, 16, 24);
  const int id = add(renderer, sphere, colors(sphere, kOrgan));
  const auto mean_x = [](const Image& image) {
    double sum = 0;
    int count = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        if (!is_background(image, x, y)) sum += x, ++count;
      }
    }
    return count ? sum / count : -1.0;
  };
  const double before = mean_x(render(renderer, camera_at(3)));
  sphere.translate(Eigen::Vector3f(1.2f, 0, 0));
  renderer.update_surface(id, sphere.positions.data(), sphere.normals.data());
  const double after = mean_x(render(renderer, camera_at(3)));
  EXPECT_LT(before, kWidth / 2.0 - 10);
  EXPECT_GT(after, kWidth / 2.0 + 10);
}

TEST(Renderer, RendersAreBitIdentical) {
  const Shape sphere = uv_sphere(Eigen::Vector3f::Zero(), 0.5f, 24, 32);
  Renderer a(kWidth, kHeight, 4);
  add(a, sphere, colors(sphere, kOrgan));
  const Image first = render(a, camera_at(3));
  const Image second = render(a, camera_at(3));
  EXPECT_EQ(first.rgb, second.rgb);
  // A second renderer alive at the same time draws the same bits, and switching between
  // them (each makes its own context current) disturbs neither.
  Renderer b(kWidth, kHeight, 4);
  add(b, sphere, colors(sphere, kOrgan));
  EXPECT_EQ(render(b, camera_at(3)).rgb, first.rgb);
  EXPECT_EQ(render(a, camera_at(3)).rgb, first.rgb);
}

TEST(Renderer, OutlivesAnotherRenderer) {
  const Shape sphere = uv_sphere(Eigen::Vector3f::Zero(), 0.5f, 24, 32);
  Renderer a(kWidth, kHeight, 0);
  add(a, sphere, colors(sphere, kOrgan));
  const Image before = render(a, camera_at(3));
  {
    Renderer b(kWidth / 2, kHeight / 2, 2);  // Made current, then destroyed.
    add(b, sphere, colors(sphere, kOrgan));
    EXPECT_GT(covered_pixels(render(b, camera_at(3))), 0);
  }
  EXPECT_EQ(render(a, camera_at(3)).rgb, before.rgb);
}

TEST(Renderer, ReadFrameReusesTheImage) {
  Renderer renderer(kWidth, kHeight, 0);
  renderer.draw(camera_at(3), front_light(), kBackground);
  Image image(kWidth, kHeight);
  const std::uint8_t* storage = image.rgb.data();
  renderer.read_frame(image);
  EXPECT_EQ(image.rgb.data(), storage);
}

/// Rows crossing the triangle's slanted left edge where the first covered pixel is
/// clearly darker than the inside: partial coverage, i.e. antialiasing.
int soft_edge_rows(int msaa) {
  Renderer renderer(kWidth, kHeight, msaa);
  const Shape tri = triangle(0.8f, 0);
  add(renderer, tri, colors(tri, scene::Color(0.9, 0.9, 0.9)));
  const Image image = render(renderer, camera_at(3));
  int soft = 0;
  for (int y = 10; y < kHeight - 10; ++y) {
    int x = 0;
    while (x < kWidth / 2 && is_background(image, x, y)) ++x;
    if (x >= kWidth / 2) continue;
    const int inside = luminance(image, x + 3, y);
    EXPECT_GT(inside, 300) << "row " << y;
    if (inside - luminance(image, x, y) > 30) ++soft;
  }
  return soft;
}

TEST(Renderer, MultisamplingSmoothsEdges) {
  EXPECT_EQ(soft_edge_rows(0), 0);
  EXPECT_GT(soft_edge_rows(4), 20);
  EXPECT_GT(soft_edge_rows(2), 10);
}

}  // namespace
}  // namespace systole::render
