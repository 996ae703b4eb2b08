#pragma once
// Catmull-Rom curves (Catmull & Rom 1974): smooth, through every key. One kernel serves the
// paths of grabs, kinematic regions and cameras, sampled drive waveforms and training's
// key poses, so they all interpolate alike.

#include <algorithm>
#include <type_traits>
#include <cstddef>
#include <vector>

namespace systole {

/// The uniform Catmull-Rom segment from p1 (u = 0) to p2 (u = 1), with p0 and p3 its
/// neighbours. T: a double or an Eigen vector or matrix (evaluated into a T).
template <class T>
T catmull_rom(const T& p0, const T& p1, const T& p2, const T& p3, double u) {
  return 0.5 * ((2 * p1) + (-p0 + p2) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u * u +
                (-p0 + 3 * p1 - 3 * p2 + p3) * u * u * u);
}

/// The curve through timed keys at time t_s: `value(key)` gives a key's point and
/// `key.time_s` its time (increasing). Held at the first and last key outside them; the end
/// keys are repeated as their own neighbours. `keys` must not be empty.
template <class Key, class Value>
auto keyed_curve(const std::vector<Key>& keys, double t_s, Value value) {
  using Point = std::decay_t<decltype(value(keys.front()))>;
  if (keys.size() == 1 || t_s <= keys.front().time_s) return Point(value(keys.front()));
  if (t_s >= keys.back().time_s) return Point(value(keys.back()));
  const auto next = std::upper_bound(keys.begin(), keys.end(), t_s, [](double t, const Key& k) { return t < k.time_s; });
  const std::size_t i = static_cast<std::size_t>(next - keys.begin()) - 1;
  const double u = (t_s - keys[i].time_s) / (keys[i + 1].time_s - keys[i].time_s);
  return catmull_rom<Point>(value(keys[i == 0 ? 0 : i - 1]), value(keys[i]), value(keys[i + 1]),
                            value(keys[std::min(i + 2, keys.size() - 1)]), u);
}

/// A periodic curve through n evenly spaced samples (sample k at k / n of the period), at
/// segment i (0 <= i < n) and fraction f in [0, 1) of it.
inline double periodic_catmull_rom(const std::vector<double>& s, std::size_t i, double f) {
  const std::size_t n = s.size();
  return catmull_rom(s[(i + n - 1) % n], s[i], s[(i + 1) % n], s[(i + 2) % n], f);
}

}  // namespace systole
