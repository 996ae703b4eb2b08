#include "overlay/labels.h"

#include <cmath>
#include <limits>

namespace systole::overlay {
namespace {

/// Area of the intersection of two rectangles. unit: px^2
double overlap_area(const Rect& a, const Rect& b) {
  const int w = std::min(a.right(), b.right()) - std::max(a.x, b.x);
  const int h = std::min(a.bottom(), b.bottom()) - std::max(a.y, b.y);
  return w > 0 && h > 0 ? double(w) * h : 0.0;
}

struct Candidate {
  PlacedLabel label;
  double cost = 0;  ///< Overlapped area; 0 = free. unit: px^2
};

}  // namespace

std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests, const Rect& frame,
                                      const std::vector<Rect>& keep_out, plot::Font& font) {
  const double size = font.size();
  const int halo = static_cast<int>(std::ceil(size / 8.0)) + 1;
  const double gap = 0.3 * size;  // Between the leader's end and the text.
  const Rect inside = frame.grown(-static_cast<int>(0.4 * size));
  std::vector<PlacedLabel> placed;
  for (const LabelRequest& r : requests) {
    const double dx = r.anchor_x - r.center_x, dy = r.anchor_y - r.center_y;
    const double len = std::hypot(dx, dy);
    const double base = len > 1e-6 ? std::atan2(dy, dx) : -std::acos(0.0);  // Straight up when at the centre.
    const double text_w = font.width(r.text), asc = font.ascent() * 0.8, desc = font.descent();
    Candidate best;
    best.cost = std::numeric_limits<double>::infinity();
    for (double distance : {2.2 * size, 3.6 * size, 5.5 * size}) {
      for (double turn_deg : {0.0, 25.0, -25.0, 50.0, -50.0, 80.0, -80.0, 115.0, -115.0, 150.0, -150.0, 180.0}) {
        const double a = base + turn_deg * std::acos(-1.0) / 180.0;
        const double px = r.anchor_x + distance * std::cos(a), py = r.anchor_y + distance * std::sin(a);
        // The text hangs off the leader's end on the side facing away from the anchor.
        const bool to_right = std::cos(a) >= -1e-9;
        PlacedLabel l;
        l.text = r.text;
        l.baseline_x = to_right ? px + gap : px - gap - text_w;
        l.baseline_y = py + 0.5 * (asc - desc);
        l.box = Rect{int(std::floor(l.baseline_x)) - halo, int(std::floor(l.baseline_y - asc)) - halo,
                     int(std::ceil(text_w)) + 2 * halo, int(std::ceil(asc + desc)) + 2 * halo};
        l.leader_x0 = px;
        l.leader_y0 = py;
        l.anchor_x = r.anchor_x;
        l.anchor_y = r.anchor_y;
        double cost = 0;
        if (!(l.box.x >= inside.x && l.box.y >= inside.y && l.box.right() <= inside.right() &&
              l.box.bottom() <= inside.bottom())) {
          cost += double(l.box.width) * l.box.height - overlap_area(l.box, inside) + 1;
        }
        for (const Rect& k : keep_out) cost += overlap_area(l.box.grown(2), k);
        for (const PlacedLabel& p : placed) {
          cost += overlap_area(l.box.grown(2), p.box);
          if (l.box.grown(3).contains(p.anchor_x, p.anchor_y)) cost += size * size;  // Hides another's anchor.
        }
        for (const LabelRequest& other : requests) {
          if (&other != &r && l.box.grown(3).contains(other.anchor_x, other.anchor_y)) cost += size * size;
        }
        if (cost < best.cost) best = {l, cost};
        if (cost == 0) break;
      }
      if (best.cost == 0) break;
    }
    best.label.free = best.cost == 0;
    placed.push_back(best.label);
  }
  return placed;
}

void draw_labels(Image& image, const std::vector<PlacedLabel>& labels, plot::Font& font, const Style& style) {
  plot::Canvas canvas(image);
  const double size = font.size();
  const double line = std::max(1.0, size / 12.0), halo = std::ceil(size / 8.0);
  // Every halo first, so no label's halo covers another's line.
  for (const PlacedLabel& l : labels) {
    canvas.line(l.leader_x0, l.leader_y0, l.anchor_x, l.anchor_y, style.halo, line + 2 * halo);
    canvas.line(l.anchor_x, l.anchor_y, l.anchor_x, l.anchor_y, style.halo, 2.5 * line + 2 * halo);
  }
  for (const PlacedLabel& l : labels) {
    canvas.line(l.leader_x0, l.leader_y0, l.anchor_x, l.anchor_y, style.ink, line);
    canvas.line(l.anchor_x, l.anchor_y, l.anchor_x, l.anchor_y, style.ink, 2.5 * line);
    font.draw_with_halo(canvas, l.text, l.baseline_x, l.baseline_y, style.ink, style.halo, halo, style.halo_alpha);
  }
}

}  // namespace systole::overlay
