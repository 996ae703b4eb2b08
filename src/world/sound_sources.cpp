#include "world/sound_sources.h"

#include <algorithm>
#include <cmath>

namespace systole::world {

RegionSize::RegionSize(const sim::Model& model, const std::vector<int>& regions) {
  for (int p = 0; p < model.particle_count(); ++p) {
    const int r = p < static_cast<int>(model.vertex_region.size()) ? model.vertex_region[static_cast<std::size_t>(p)] : -1;
    if (std::find(regions.begin(), regions.end(), r) != regions.end()) particles_.push_back(p);
  }
}

double RegionSize::measure(const Eigen::Matrix3Xd& x) const {
  if (particles_.empty()) return 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int p : particles_) centroid += x.col(p);  // Fixed order: the same sum every run.
  centroid /= static_cast<double>(particles_.size());
  double sum = 0;
  for (int p : particles_) sum += (x.col(p) - centroid).norm();
  return sum / static_cast<double>(particles_.size());
}

double parabolic_peak_s(const std::vector<Sample>& s, std::size_t i) {
  if (i == 0 || i + 1 >= s.size()) return s[i].time_s;
  const double a = s[i - 1].value, b = s[i].value, c = s[i + 1].value;
  const double curvature = a - 2 * b + c;
  const double step = 0.5 * (s[i + 1].time_s - s[i - 1].time_s);
  if (curvature == 0) return s[i].time_s;
  // Vertex of the parabola through (-1, a), (0, b), (1, c): x = (a - c) / (2 (a - 2b + c)).
  const double offset = std::clamp(0.5 * (a - c) / curvature, -0.5, 0.5);
  return s[i].time_s + offset * step;
}

std::vector<CycleEvent> detect_cycle_events(const std::vector<Sample>& size, double hysteresis) {
  std::vector<CycleEvent> events;
  if (size.size() < 3) return events;
  // A turn counts once the size has moved back by `hysteresis` of its whole range over the
  // run: ringing near a plateau is a small share of a beat's swing, a beat never is (the
  // run is known whole: the soundtrack is made before the frames, clip/soundtrack.h).
  double lo = size.front().value, hi = lo;
  for (const Sample& s : size) lo = std::min(lo, s.value), hi = std::max(hi, s.value);
  const double threshold = hysteresis * (hi - lo);
  if (!(threshold > 0)) return events;
  std::size_t extreme = 0;
  int direction = 0;  // +1 rising (looking for a maximum), -1 falling, 0 not yet known.
  std::size_t last_refill = 0;
  bool have_refill = false;
  const auto add_peak_refill = [&](std::size_t from, std::size_t to) {
    // The fastest growth between a refill onset and the next shrink onset (central differences).
    std::size_t best = 0;
    double best_rate = 0;
    std::vector<Sample> rate;
    for (std::size_t i = std::max<std::size_t>(from, 1); i + 1 <= to && i + 1 < size.size(); ++i) {
      rate.push_back({size[i].time_s, size[i + 1].value - size[i - 1].value});
      if (rate.back().value > best_rate) {
        best_rate = rate.back().value;
        best = rate.size() - 1;
      }
    }
    if (best_rate > 0) events.push_back({CycleEventKind::kPeakRefill, parabolic_peak_s(rate, best)});
  };
  for (std::size_t i = 1; i < size.size(); ++i) {
    const double v = size[i].value;
    if (direction == 0) {
      // The first movement away from the start says which turning point comes first.
      if (std::abs(v - size.front().value) > threshold) {
        direction = v > size.front().value ? 1 : -1;
        extreme = i;
      }
      continue;
    }
    if ((direction > 0 && v > size[extreme].value) || (direction < 0 && v < size[extreme].value)) extreme = i;
    const double e_now = size[extreme].value;
    if (direction > 0 && e_now - v > threshold) {
      // A maximum: the chamber started to shrink at `extreme`.
      events.push_back({CycleEventKind::kSystoleStart, parabolic_peak_s(size, extreme)});
      if (have_refill) add_peak_refill(last_refill, extreme);
      direction = -1;
      extreme = i;
    } else if (direction < 0 && v - e_now > threshold) {
      events.push_back({CycleEventKind::kSystoleEnd, parabolic_peak_s(size, extreme)});
      last_refill = extreme;
      have_refill = true;
      direction = 1;
      extreme = i;
    }
  }
  std::stable_sort(events.begin(), events.end(), [](const CycleEvent& a, const CycleEvent& b) { return a.time_s < b.time_s; });
  return events;
}

}  // namespace systole::world
