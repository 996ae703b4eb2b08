#include "render/fxaa.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace systole::render {
namespace {

constexpr float kEdgeThreshold = 1.0f / 8.0f;     // Least contrast, relative to the local max luma.
constexpr float kEdgeThresholdMin = 1.0f / 24.0f; // Least contrast in dark areas, unit: luma.
constexpr float kReduceMul = 1.0f / 8.0f;
constexpr float kReduceMin = 1.0f / 128.0f;
constexpr float kSpanMax = 8.0f;                  // Longest blur along an edge, unit: px

struct Rgb {
  float r = 0, g = 0, b = 0;
};

Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
Rgb operator*(float s, Rgb a) { return {s * a.r, s * a.g, s * a.b}; }

constexpr std::array<float, 3> kLumaWeights = {0.299f, 0.587f, 0.114f};  // Rec. 601, of R, G and B.

float luma(float r, float g, float b) { return kLumaWeights[0] * r + kLumaWeights[1] * g + kLumaWeights[2] * b; }

/// Bilinear sample at (x, y) in pixel units (pixel centres at integers), clamped at the border.
Rgb sample(const Image& image, float x, float y) {
  x = std::clamp(x, 0.0f, static_cast<float>(image.width - 1));
  y = std::clamp(y, 0.0f, static_cast<float>(image.height - 1));
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  const std::uint8_t* p00 = image.pixel(x0, y0);
  const std::uint8_t* p10 = image.pixel(x1, y0);
  const std::uint8_t* p01 = image.pixel(x0, y1);
  const std::uint8_t* p11 = image.pixel(x1, y1);
  float c[3];
  for (int k = 0; k < 3; ++k) {
    const float top = static_cast<float>(p00[k]) + fx * static_cast<float>(p10[k] - p00[k]);
    const float bottom = static_cast<float>(p01[k]) + fx * static_cast<float>(p11[k] - p01[k]);
    c[k] = (top + fy * (bottom - top)) * (1.0f / 255.0f);
  }
  return {c[0], c[1], c[2]};
}

/// The first index in [0, n) at which a and b differ, or n: eight bytes a comparison.
std::size_t first_difference(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) {
  std::size_t i = 0;
  for (std::uint64_t u, v; i + 8 <= n; i += 8) {
    std::memcpy(&u, a + i, 8);
    std::memcpy(&v, b + i, 8);
    if (u != v) break;
  }
  while (i < n && a[i] == b[i]) ++i;
  return i;
}

/// The last index in [0, n) at which a and b differ, or n when they are equal.
std::size_t last_difference(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) {
  std::size_t end = n;  // Every index from end on is equal.
  for (std::uint64_t u, v; end >= 8; end -= 8) {
    std::memcpy(&u, a + end - 8, 8);
    std::memcpy(&v, b + end - 8, 8);
    if (u != v) break;
  }
  while (end > 0 && a[end - 1] == b[end - 1]) --end;
  return end == 0 ? n : end - 1;
}

std::uint8_t to_byte(float c) { return static_cast<std::uint8_t>(std::clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f); }

/// The filtered colour of an edge pixel (x, y) of `source`, from the luma rows above, at
/// and below it.
Rgb filtered(const Image& source, const float* above, const float* row, const float* below, int x, int y) {
  const float l_nw = above[x - 1], l_ne = above[x + 1], l_sw = below[x - 1], l_se = below[x + 1];
  const float l_m = row[x];
  const float l_min = std::min({l_m, l_nw, l_ne, l_sw, l_se});
  const float l_max = std::max({l_m, l_nw, l_ne, l_sw, l_se});

  // Along the edge: across the luma gradient (image rows grow downwards).
  float dx = -((l_nw + l_ne) - (l_sw + l_se));
  float dy = -((l_nw + l_sw) - (l_ne + l_se));
  const float reduce = std::max((l_nw + l_ne + l_sw + l_se) * (0.25f * kReduceMul), kReduceMin);
  const float scale = 1.0f / (std::min(std::abs(dx), std::abs(dy)) + reduce);
  dx = std::clamp(dx * scale, -kSpanMax, kSpanMax);
  dy = std::clamp(dy * scale, -kSpanMax, kSpanMax);
  const float fx = static_cast<float>(x), fy = static_cast<float>(y);
  const auto at = [&](float t) { return sample(source, fx + t * dx, fy + t * dy); };
  const Rgb a = 0.5f * (at(1.0f / 3.0f - 0.5f) + at(2.0f / 3.0f - 0.5f));
  const Rgb b = 0.5f * a + 0.25f * (at(-0.5f) + at(0.5f));
  const float l_b = luma(b.r, b.g, b.b);
  return (l_b < l_min || l_b > l_max) ? a : b;
}

}  // namespace

void Fxaa::apply(Image& image) {
  Box box;
  if (!filtered_box(image, box)) return;
  prepare_source(image, box);
  for (int y = box.ya; y <= box.yb; ++y) filter_row(image, y, box.xa, box.xb);
}

bool Fxaa::filtered_box(const Image& image, Box& box) {
  const int w = image.width, h = image.height;
  if (w < 3 || h < 3) return false;
  // Only where the frame is not the background: a pixel whose diagonal neighbours and itself
  // all have the first pixel's colour has no contrast and is left as it is, so the pixels
  // outside the box of the others, grown by one, need no luma and no test.
  const std::uint8_t* first = image.pixel(0, 0);
  const std::size_t row_bytes = 3 * static_cast<std::size_t>(w);
  background_.resize(row_bytes);
  for (std::size_t k = 0; k < row_bytes; ++k) background_[k] = first[k % 3];
  int x0 = w, x1 = -1, y0 = h, y1 = -1;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* row = image.row(y);
    const std::size_t left = first_difference(row, background_.data(), row_bytes);
    if (left == row_bytes) continue;
    const std::size_t right = last_difference(row, background_.data(), row_bytes);
    x0 = std::min(x0, static_cast<int>(left / 3)), x1 = std::max(x1, static_cast<int>(right / 3));
    y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  if (x1 < 0) return false;  // One colour.
  // Border pixels are left as they are: the corners read outside the frame.
  box.xa = std::max(1, x0 - 1), box.xb = std::min(w - 2, x1 + 1);
  box.ya = std::max(1, y0 - 1), box.yb = std::min(h - 2, y1 + 1);
  return box.xa <= box.xb && box.ya <= box.yb;
}

void Fxaa::prepare_source(const Image& image, const Box& box) {
  const int w = image.width, h = image.height;
  // The taps reach half the longest span and a pixel beyond it: those rows of the input are copied.
  const int reach = static_cast<int>(std::ceil(0.5f * kSpanMax)) + 1;
  const int copy_a = std::max(0, box.ya - reach), copy_b = std::min(h - 1, box.yb + reach);
  source_.width = w;
  source_.height = h;
  source_.rgb.resize(image.rgb.size());  // No allocation once sized.
  std::copy(image.row(copy_a), image.row(copy_b) + 3 * static_cast<std::size_t>(w), source_.row(copy_a));
  luma_.resize(static_cast<std::size_t>(w) * h);
  // luma()'s three products looked up by byte (the same floats, added in the same order).
  static const std::array<std::array<float, 256>, 3> weighted = [] {
    std::array<std::array<float, 256>, 3> t{};
    for (std::size_t k = 0; k < 3; ++k) {
      for (std::size_t v = 0; v < 256; ++v) t[k][v] = kLumaWeights[k] * static_cast<float>(v);
    }
    return t;
  }();
  for (int y = box.ya - 1; y <= box.yb + 1; ++y) {
    const std::uint8_t* p = source_.pixel(box.xa - 1, y);
    float* out = &luma_[static_cast<std::size_t>(y) * w];
    for (int x = box.xa - 1; x <= box.xb + 1; ++x, p += 3) {
      out[x] = (weighted[0][p[0]] + weighted[1][p[1]] + weighted[2][p[2]]) * (1.0f / 255.0f);
    }
  }
  edge_.resize(static_cast<std::size_t>(w));
}

void Fxaa::filter_row(Image& image, int y, int xa, int xb) {
  const int w = image.width;
  const float* above = &luma_[static_cast<std::size_t>(y - 1) * w];
  const float* row = above + w;
  const float* below = row + w;
  // The contrast test for the whole row first, without branches, so the compiler
  // vectorizes it (most pixels fail it); then the few that pass. min and max are exact,
  // so the test is the same as per pixel.
  for (int x = xa; x <= xb; ++x) {
    const float l_m = row[x];
    const float l_min = std::min(std::min(std::min(above[x - 1], above[x + 1]), std::min(below[x - 1], below[x + 1])), l_m);
    const float l_max = std::max(std::max(std::max(above[x - 1], above[x + 1]), std::max(below[x - 1], below[x + 1])), l_m);
    edge_[static_cast<std::size_t>(x)] = l_max - l_min >= std::max(kEdgeThresholdMin, l_max * kEdgeThreshold) ? 1u : 0u;
  }
  for (int x = xa; x <= xb; ++x) {
    if (!edge_[static_cast<std::size_t>(x)]) continue;
    const Rgb out = filtered(source_, above, row, below, x, y);
    std::uint8_t* p = image.row(y) + 3 * static_cast<std::size_t>(x);
    p[0] = to_byte(out.r);
    p[1] = to_byte(out.g);
    p[2] = to_byte(out.b);
  }
}

}  // namespace systole::render
