#include "encode/palette.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace systole::encode {
namespace {

constexpr int kBits = 6;
constexpr int kSide = 1 << kBits;

int bin_of(int r, int g, int b) { return (r >> (8 - kBits)) << (2 * kBits) | (g >> (8 - kBits)) << kBits | (b >> (8 - kBits)); }

/// A box of histogram bins for median cut.
struct Box {
  std::vector<int> bins;  ///< Indices of occupied bins.
  std::uint64_t count = 0;
  int axis = 0;           ///< Longest side.
  int extent = 0;         ///< Its length. unit: bins
};

}  // namespace

PaletteBuilder::PaletteBuilder() : bins_(static_cast<std::size_t>(kSide) * kSide * kSide) {}

void PaletteBuilder::add(const Image& image) {
  const std::uint8_t* p = image.rgb.data();
  const std::size_t n = image.rgb.size() / 3;
  for (std::size_t i = 0; i < n; ++i, p += 3) {
    Bin& bin = bins_[static_cast<std::size_t>(bin_of(p[0], p[1], p[2]))];
    ++bin.count;
    for (int c = 0; c < 3; ++c) bin.sum[c] += p[c];
  }
}

std::vector<PaletteColor> PaletteBuilder::build(int max_colors) const {
  if (max_colors < 1 || max_colors > 256) throw std::invalid_argument("palette size must be in 1..256");
  auto measure = [&](Box& box) {
    int lo[3] = {kSide, kSide, kSide}, hi[3] = {-1, -1, -1};
    box.count = 0;
    for (int b : box.bins) {
      const int c[3] = {b >> (2 * kBits), (b >> kBits) & (kSide - 1), b & (kSide - 1)};
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
      box.count += bins_[static_cast<std::size_t>(b)].count;
    }
    box.axis = 0;
    for (int k = 1; k < 3; ++k)
      if (hi[k] - lo[k] > hi[box.axis] - lo[box.axis]) box.axis = k;
    box.extent = hi[box.axis] - lo[box.axis];
  };
  std::vector<Box> boxes(1);
  for (int b = 0; b < kSide * kSide * kSide; ++b)
    if (bins_[static_cast<std::size_t>(b)].count > 0) boxes[0].bins.push_back(b);
  if (boxes[0].bins.empty()) return {PaletteColor{0, 0, 0}};
  measure(boxes[0]);
  while (static_cast<int>(boxes.size()) < max_colors) {
    // Split the box with the most pixels times extent: big, spread-out groups first.
    int pick = -1;
    double best = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const double score = static_cast<double>(boxes[i].count) * boxes[i].extent;
      if (boxes[i].bins.size() > 1 && score > best) best = score, pick = static_cast<int>(i);
    }
    if (pick < 0) break;
    Box& box = boxes[static_cast<std::size_t>(pick)];
    const int shift = box.axis == 0 ? 2 * kBits : box.axis == 1 ? kBits : 0;
    auto coord = [&](int b) { return (b >> shift) & (kSide - 1); };
    std::stable_sort(box.bins.begin(), box.bins.end(), [&](int a, int b) { return coord(a) < coord(b); });
    // Cut at the weighted median, never leaving a side empty.
    std::uint64_t acc = 0;
    std::size_t cut = 1;
    for (std::size_t i = 0; i + 1 < box.bins.size(); ++i) {
      acc += bins_[static_cast<std::size_t>(box.bins[i])].count;
      cut = i + 1;
      if (2 * acc >= box.count) break;
    }
    Box other;
    other.bins.assign(box.bins.begin() + static_cast<std::ptrdiff_t>(cut), box.bins.end());
    box.bins.resize(cut);
    measure(box);
    measure(other);
    boxes.push_back(std::move(other));
  }
  std::vector<PaletteColor> palette;
  for (const Box& box : boxes) {
    std::uint64_t sum[3] = {0, 0, 0};
    for (int b : box.bins)
      for (int c = 0; c < 3; ++c) sum[c] += bins_[static_cast<std::size_t>(b)].sum[c];
    PaletteColor color;
    for (int c = 0; c < 3; ++c) color[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>((sum[c] + box.count / 2) / box.count);
    palette.push_back(color);
  }
  return palette;
}

PaletteMapper::PaletteMapper(std::vector<PaletteColor> palette, double dither)
    : palette_(std::move(palette)), cache_(static_cast<std::size_t>(kSide) * kSide * kSide, -1) {
  if (palette_.empty() || palette_.size() > 256) throw std::invalid_argument("palette size must be in 1..256");
  // The 8x8 Bayer matrix, recursively: M(2n) = [4M, 4M+2; 4M+3, 4M+1].
  int m[8][8] = {{0}};
  for (int size = 1; size < 8; size *= 2)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const int v = m[y][x] * 4;
        m[y][x] = v;
        m[y][x + size] = v + 2;
        m[y + size][x] = v + 3;
        m[y + size][x + size] = v + 1;
      }
  for (int i = 0; i < 64; ++i) offset_[static_cast<std::size_t>(i)] = static_cast<int>(dither * ((m[i / 8][i % 8] + 0.5) / 64.0 - 0.5));
}

std::uint8_t PaletteMapper::nearest(int r, int g, int b) {
  std::int16_t& cached = cache_[static_cast<std::size_t>(bin_of(r, g, b))];
  if (cached >= 0) return static_cast<std::uint8_t>(cached);
  // The bin's centre stands for every colour in it.
  const int half = 1 << (7 - kBits);
  const int c[3] = {(r & ~(2 * half - 1)) + half, (g & ~(2 * half - 1)) + half, (b & ~(2 * half - 1)) + half};
  int best = 0, best_d = std::numeric_limits<int>::max();
  for (std::size_t i = 0; i < palette_.size(); ++i) {
    int d = 0;
    for (int k = 0; k < 3; ++k) {
      const int e = c[k] - palette_[i][static_cast<std::size_t>(k)];
      d += e * e;
    }
    if (d < best_d) best_d = d, best = static_cast<int>(i);
  }
  cached = static_cast<std::int16_t>(best);
  return static_cast<std::uint8_t>(best);
}

void PaletteMapper::map(const Image& image, std::vector<std::uint8_t>& indices) {
  indices.resize(static_cast<std::size_t>(image.width) * image.height);
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* p = image.row(y);
    std::uint8_t* out = indices.data() + static_cast<std::size_t>(y) * image.width;
    for (int x = 0; x < image.width; ++x, p += 3) {
      const int o = offset_[static_cast<std::size_t>((y & 7) * 8 + (x & 7))];
      out[x] = nearest(std::clamp(p[0] + o, 0, 255), std::clamp(p[1] + o, 0, 255), std::clamp(p[2] + o, 0, 255));
    }
  }
}

}  // namespace systole::encode
