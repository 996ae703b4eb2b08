#include "overlay/cards.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "plot/text.h"

namespace systole::overlay {
namespace {

plot::Rgb rgb_of(const scene::Color& c) {
  auto level = [](double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  return {level(c.x()), level(c.y()), level(c.z())};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t at = 0;
  for (std::size_t nl; (nl = text.find('\n', at)) != std::string::npos; at = nl + 1) lines.push_back(text.substr(at, nl - at));
  lines.push_back(text.substr(at));
  while (lines.size() > 1 && lines.back().empty()) lines.pop_back();  // A YAML block's final newline.
  return lines;
}

/// The largest size up to `px` at which `text` fits in `max_width`. unit: px
int fitting_size(plot::Font& font, const std::string& text, int px, double max_width) {
  font.size(px);
  const double w = font.width(text);
  if (w > max_width && w > 0) {
    px = std::max(6, static_cast<int>(px * max_width / w));
    font.size(px);
  }
  return px;
}

/// Darkens the rectangle [x0, x1) x [y0, y1) towards black by `alpha`.
void shade(Image& image, int x0, int y0, int x1, int y1, double alpha) {
  plot::Canvas(image).fill(x0, y0, x1, y1, {0, 0, 0}, alpha);
}

}  // namespace

double fade_opacity(double t, double from_s, double to_s, double fade_s) {
  if (t < from_s || t >= to_s) return 0;
  if (fade_s <= 0) return 1;
  return std::clamp(std::min(t - from_s, to_s - t) / fade_s, 0.0, 1.0);
}

CardPainter::CardPainter(const scene::Scene& scene) : scene_(scene) {
  if (!scene.cards.empty() || !scene.captions.empty()) font_ = std::make_unique<plot::Font>();
  for (const auto& card : scene.cards) {
    card_first_.push_back(card_frames_);
    card_frames_ += std::max(1, static_cast<int>(std::lround(card.duration_s * scene.output.fps)));
  }
}

CardPainter::~CardPainter() = default;

void CardPainter::draw_card(int k, Image& image) {
  const auto& out = scene_.output;
  const plot::Rgb background = rgb_of(out.background);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) std::copy(background.begin(), background.end(), image.rgb.begin() + static_cast<std::ptrdiff_t>(i));
  const auto card_index = static_cast<std::size_t>(std::upper_bound(card_first_.begin(), card_first_.end(), k) - card_first_.begin() - 1);
  const scene::Card& card = scene_.cards[card_index];
  const double t = (k - card_first_[card_index]) / out.fps;
  const double opacity = fade_opacity(t, 0, card.duration_s, card.fade_s);
  if (opacity <= 0) return;
  // The first line is the title; the others are set smaller beneath it.
  const std::vector<std::string> lines = lines_of(card.text);
  const int title_px = std::max(6, static_cast<int>(std::lround(card.size * image.height)));
  std::vector<int> px(lines.size());
  double block = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    px[i] = fitting_size(*font_, lines[i], i == 0 ? title_px : std::max(6, title_px * 11 / 20), 0.9 * image.width);
    block += (font_->ascent() + font_->descent()) * (i == 0 ? 1.25 : 1.1);
  }
  double top = (image.height - block) / 2;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    font_->size(px[i]);
    const double x = (image.width - font_->width(lines[i])) / 2;
    plot::Canvas canvas(image);
    font_->draw(canvas, lines[i], x, top + font_->ascent(), rgb_of(card.color), false, opacity);
    top += (font_->ascent() + font_->descent()) * (i == 0 ? 1.25 : 1.1);
  }
}

void CardPainter::draw_captions(int clip_frame, Image& image) {
  if (scene_.captions.empty()) return;
  const double t = clip_frame / scene_.output.fps;
  double bottom = image.height * 0.95;  // Baseline area of the lowest caption; later ones stack above.
  for (const scene::Caption& caption : scene_.captions) {
    const double opacity = fade_opacity(t, caption.from_s, caption.to_s, caption.fade_s);
    if (opacity <= 0) continue;
    const int px = fitting_size(*font_, caption.text, std::max(6, static_cast<int>(std::lround(caption.size * image.height))),
                                0.9 * image.width);
    const double w = font_->width(caption.text), h = (font_->ascent() + font_->descent()), pad = 0.35 * px;
    const double x = (image.width - w) / 2, top = bottom - h;
    // A dark band keeps the words readable over a bright organ.
    shade(image, static_cast<int>(std::floor(x - pad)), static_cast<int>(std::floor(top - pad / 2)),
          static_cast<int>(std::ceil(x + w + pad)), static_cast<int>(std::ceil(bottom + pad / 2)), 0.55 * opacity);
    plot::Canvas canvas(image);
    font_->draw(canvas, caption.text, x, top + font_->ascent(), rgb_of(caption.color), false, opacity);
    bottom = top - pad * 1.5;
  }
}

}  // namespace systole::overlay
