#include "render/fxaa.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace systole::render {
namespace {

/// White below the line y = x / 3 + 10 (a shallow slope: long stair steps), black above.
Image stairs(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::uint8_t v = 3 * y > x + 30 ? 255 : 0;
      std::uint8_t* p = image.row(y) + 3 * x;
      p[0] = p[1] = p[2] = v;
    }
  }
  return image;
}

int grey_pixels(const Image& image) {
  int n = 0;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) n += image.rgb[i] > 10 && image.rgb[i] < 245;
  return n;
}

TEST(Fxaa, SoftensStairStepsAlongAnEdge) {
  Image image = stairs(120, 80);
  ASSERT_EQ(grey_pixels(image), 0);
  Fxaa fxaa;
  fxaa.apply(image);
  // Most columns the edge crosses get a blended pixel.
  EXPECT_GT(grey_pixels(image), 60);
  // Far from the edge nothing moves.
  EXPECT_EQ(image.pixel(110, 5)[0], 0);
  EXPECT_EQ(image.pixel(5, 75)[0], 255);
}

TEST(Fxaa, LeavesFlatAndSmoothImagesAlone) {
  Image image(64, 48);
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      std::uint8_t* p = image.row(y) + 3 * x;
      p[0] = static_cast<std::uint8_t>(40 + x);  // A gentle gradient, like smooth shading.
      p[1] = 20;
      p[2] = static_cast<std::uint8_t>(30 + y);
    }
  }
  const Image before = image;
  Fxaa fxaa;
  fxaa.apply(image);
  EXPECT_EQ(image.rgb, before.rgb);
}

TEST(Fxaa, SameBitsEveryTimeAndReusesItsBuffers) {
  Fxaa fxaa;
  Image a = stairs(120, 80);
  fxaa.apply(a);
  Image b = stairs(120, 80);
  const std::uint8_t* storage = b.rgb.data();
  fxaa.apply(b);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_EQ(b.rgb.data(), storage) << "in place";
}

}  // namespace
}  // namespace systole::render
