#include "chart/axis.h"

#include <cmath>
#include <cstdio>

namespace systole::chart {

double axis_fraction(const Axis& axis, double value) {
  if (axis.scale == Scale::kLog) {
    return (std::log10(value) - std::log10(axis.min)) / (std::log10(axis.max) - std::log10(axis.min));
  }
  return (value - axis.min) / (axis.max - axis.min);
}

std::vector<double> ticks(const Axis& axis) {
  std::vector<double> out;
  if (axis.scale == Scale::kLog) {
    const int first = int(std::floor(std::log10(axis.min))), last = int(std::ceil(std::log10(axis.max)));
    // Decades only over a wide range; 1-2-5 over a few decades; every mantissa within one.
    const double span = std::log10(axis.max / axis.min);
    const std::vector<double> mantissas = span > 3 ? std::vector<double>{1} : span > 1 ? std::vector<double>{1, 2, 5}
                                                                                        : std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9};
    for (int e = first; e <= last; ++e) {
      for (double m : mantissas) {
        const double v = m * std::pow(10.0, e);
        if (v >= axis.min * (1 - 1e-9) && v <= axis.max * (1 + 1e-9)) out.push_back(v);
      }
    }
    return out;
  }
  const double raw = (axis.max - axis.min) / 6.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * decade;
    if (step >= raw) break;
  }
  for (double v = std::ceil(axis.min / step) * step; v <= axis.max + 1e-9 * step; v += step) out.push_back(v);
  return out;
}

std::string tick_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return text;
}

}  // namespace systole::chart
