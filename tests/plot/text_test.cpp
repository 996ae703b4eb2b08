// Drawing with coverage and setting text (plot/text.h): UTF-8 decoding against known
// encodings, blending's end points, filled rectangles and lines where they were asked for,
// halos that grow a mask, and text that lands at its pen position and width.

#include "plot/text.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/image.h"

namespace systole::plot {
namespace {

const Rgb kWhite{255, 255, 255}, kRed{200, 10, 30};

bool touched(const Image& img, int x, int y) {
  const std::uint8_t* p = img.pixel(x, y);
  return p[0] || p[1] || p[2];
}

TEST(Utf8, DecodesOneToFourByteSequences) {
  EXPECT_EQ(decode_utf8("Ab"), U"Ab");
  EXPECT_EQ(decode_utf8("\xc3\xa9"), U"\u00e9");              // é
  EXPECT_EQ(decode_utf8("\xce\x94P"), U"\u0394P");            // ΔP
  EXPECT_EQ(decode_utf8("\xe2\x82\xac"), U"\u20ac");          // €
  EXPECT_EQ(decode_utf8("\xf0\x9f\x98\x80"), U"\U0001F600");  // an emoji, beyond the BMP
  EXPECT_EQ(decode_utf8(""), U"");
}

TEST(Utf8, AMalformedByteReadsAsTheReplacementCharacter) {
  EXPECT_EQ(decode_utf8("a\xff" "b"), U"a\uFFFD" U"b");          // Never a lead byte.
  EXPECT_EQ(decode_utf8("\x80"), U"\uFFFD");                    // A continuation without a lead.
  EXPECT_EQ(decode_utf8("x\xe2\x82"), U"x\uFFFD\uFFFD");        // Cut short at the end.
  EXPECT_EQ(decode_utf8("\xc3" "A"), U"\uFFFD" U"A");           // A lead without its continuation.
}

TEST(Canvas, BlendGoesFromTheImageToTheColour) {
  Image img(4, 1);
  Canvas canvas(img);
  canvas.blend(0, 0, kWhite, 0.0);
  canvas.blend(1, 0, kWhite, 1.0);
  canvas.blend(2, 0, kWhite, 0.5);
  canvas.blend(3, 0, kWhite, 7.0);  // Clamped to 1.
  EXPECT_FALSE(touched(img, 0, 0));
  EXPECT_EQ(img.pixel(1, 0)[0], 255);
  EXPECT_EQ(img.pixel(2, 0)[0], 128);  // Halfway from 0 to 255, rounded.
  EXPECT_EQ(img.pixel(3, 0)[0], 255);
  canvas.blend(-1, 0, kWhite, 1.0);  // Outside: ignored, no crash.
  canvas.blend(4, 0, kWhite, 1.0);
}

TEST(Canvas, FillCoversExactlyItsHalfOpenRectangle) {
  Image img(10, 8);
  Canvas canvas(img);
  canvas.fill(2, 3, 6, 5, kRed);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 10; ++x) {
      const bool inside = x >= 2 && x < 6 && y >= 3 && y < 5;
      EXPECT_EQ(touched(img, x, y), inside) << x << "," << y;
      if (inside) {
        EXPECT_EQ(img.pixel(x, y)[0], 200);
      }
    }
  }
  canvas.fill(-5, -5, 100, 100, kWhite, 0.5);  // Clipped to the image.
  EXPECT_EQ(img.pixel(0, 0)[1], 128);
}

TEST(Canvas, ALineCoversItsPathAndNothingFarFromIt) {
  Image img(40, 40);
  Canvas canvas(img);
  canvas.line(5, 20, 35, 20, kWhite, 2.0);
  for (int x = 6; x <= 34; ++x) EXPECT_GT(img.pixel(x, 20)[0], 200) << x;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      if (std::abs(y - 20) > 3 || x < 2 || x > 38) {
        EXPECT_FALSE(touched(img, x, y)) << x << "," << y;
      }
    }
  }
}

TEST(Mask, DilatingGrowsTheCoverageByTheRadius) {
  Mask m{10, 20, 5, 5, std::vector<float>(25, 0.0f)};
  m.coverage[2 * 5 + 2] = 1.0f;  // One covered pixel at (12, 22).
  const Mask d = m.dilated(2.0);
  EXPECT_LE(d.x0, 10 - 2);
  EXPECT_LE(d.y0, 20 - 2);
  const auto at_image = [&](int x, int y) { return d.at(x - d.x0, y - d.y0); };
  // A disc of radius 2 with a one-pixel soft edge: full within 1.5 px, half at 2 px.
  EXPECT_FLOAT_EQ(at_image(12, 22), 1.0f);
  EXPECT_FLOAT_EQ(at_image(13, 22), 1.0f);
  EXPECT_FLOAT_EQ(at_image(13, 23), 1.0f);  // 1.41 px away.
  EXPECT_FLOAT_EQ(at_image(14, 22), 0.5f);
  EXPECT_FLOAT_EQ(at_image(12, 20), 0.5f);
  EXPECT_EQ(at_image(15, 22), 0.0f);  // Beyond radius + the soft edge.
  EXPECT_EQ(at_image(14, 24), 0.0f);  // The disc's corner: 2.83 px away.
  // Never less than the original anywhere.
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x) EXPECT_GE(at_image(10 + x, 20 + y), m.at(x, y));
}

class FontTest : public ::testing::Test {
 protected:
  Font font;
};

TEST_F(FontTest, WidthAddsUpAndScalesWithTheSize) {
  font.size(20);
  EXPECT_EQ(font.size(), 20);
  EXPECT_EQ(font.width(""), 0.0);
  const double one = font.width("m"), three = font.width("mmm");
  EXPECT_GT(one, 5.0);
  EXPECT_NEAR(three, 3 * one, 1e-9);
  font.size(40);
  EXPECT_NEAR(font.width("mmm"), 2 * three, 0.1 * three);
  EXPECT_GT(font.ascent(), 0.5 * 40 * 0.5);
  EXPECT_LT(font.ascent(), 40.0);
  EXPECT_GE(font.descent(), 0.0);
}

TEST_F(FontTest, TextLandsRightOfItsPenAboveItsBaselineAndWithinItsWidth) {
  font.size(24);
  Image img(200, 60);
  Canvas canvas(img);
  const double x = 20, y = 40;
  const double w = font.width("Heart");
  font.draw(canvas, "Heart", x, y, kWhite);
  int lit = 0;
  for (int py = 0; py < 60; ++py) {
    for (int px = 0; px < 200; ++px) {
      if (!touched(img, px, py)) continue;
      ++lit;
      EXPECT_GE(px, x - 2) << px << "," << py;
      EXPECT_LE(px, x + w + 2) << px << "," << py;
      EXPECT_GE(py, y - font.ascent() - 2) << px << "," << py;
      EXPECT_LE(py, y + font.descent() + 2) << px << "," << py;
    }
  }
  EXPECT_GT(lit, 50);
}

TEST_F(FontTest, DrawingBlendsWhatTheMaskCoversAndIsDeterministic) {
  font.size(18);
  Image a(120, 40), b(120, 40);
  Canvas ca(a), cb(b);
  font.draw(ca, "Systole", 5, 30, kWhite);
  font.draw(cb, "Systole", 5, 30, kWhite);
  EXPECT_EQ(a.rgb, b.rgb);
  const Mask m = font.mask("Systole", 5, 30);
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      const int px = m.x0 + x, py = m.y0 + y;
      if (px < 0 || py < 0 || px >= 120 || py >= 40) continue;
      EXPECT_NEAR(a.pixel(px, py)[0], 255.0 * std::min(1.0f, m.at(x, y)), 1.0) << px << "," << py;
    }
  }
}

TEST_F(FontTest, AHaloSurroundsTheGlyphs) {
  font.size(18);
  Image plain(120, 40), haloed(120, 40);
  Canvas cp(plain), ch(haloed);
  font.draw(cp, "ECG", 10, 30, kWhite);
  font.draw_with_halo(ch, "ECG", 10, 30, kWhite, kRed, 2.0, 1.0);
  int halo_only = 0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 120; ++x) {
      if (touched(haloed, x, y) && !touched(plain, x, y)) ++halo_only;
      if (touched(plain, x, y)) {
        EXPECT_TRUE(touched(haloed, x, y));
      }
    }
  }
  EXPECT_GT(halo_only, 50);
}

}  // namespace
}  // namespace systole::plot
