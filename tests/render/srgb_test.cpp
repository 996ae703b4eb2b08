// The organ shader's sRGB encoding (shaders/organ.frag.glsl, linear_to_srgb): its power
// segment is a polynomial in c^(1/4) rather than pow. These tests read the shipped
// coefficients from the embedded shader and evaluate them as the shader does (in float),
// against the exact transfer function.

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "render/shader_source.h"

namespace systole::render {
namespace {

/// The six coefficients of `vec3 power = ...` in the shader, constant term first.
std::vector<float> shipped_coefficients() {
  const std::string source(shader_source("organ.frag.glsl"));
  const std::size_t at = source.find("vec3 power =");
  if (at == std::string::npos) return {};
  const std::string line = source.substr(at, source.find(';', at) - at);
  std::vector<float> out;
  const std::regex number(R"([-+]?\d+\.\d+)");
  for (auto it = std::sregex_iterator(line.begin(), line.end(), number); it != std::sregex_iterator(); ++it) {
    out.push_back(std::stof(it->str()));
  }
  return out;
}

/// The shader's power segment, in float as the GPU computes it.
float shader_power_segment(const std::vector<float>& k, float c) {
  const float u = std::sqrt(std::sqrt(c));
  float p = k[5];
  for (int i = 4; i >= 0; --i) p = k[static_cast<std::size_t>(i)] + u * p;
  return 1.055f * p - 0.055f;
}

double exact_srgb(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }

TEST(SrgbEncoding, TheShippedFitIsWithinAHundredthOfAnEightBitStep) {
  const std::vector<float> k = shipped_coefficients();
  ASSERT_EQ(k.size(), 6u) << "shaders/organ.frag.glsl no longer has its six-coefficient `vec3 power =` line";
  double worst = 0;
  int rounded_apart = 0, samples = 0;
  for (double c = 0.0031308; c <= 1.0; c += 1.0 / 200000, ++samples) {
    const double approx = shader_power_segment(k, static_cast<float>(c));
    worst = std::max(worst, std::abs(approx - exact_srgb(c)) * 255);
    rounded_apart += std::lround(approx * 255) != std::lround(exact_srgb(c) * 255);
  }
  EXPECT_LT(worst, 0.01) << "in 8-bit steps";
  // Only values within `worst` of a rounding boundary can land a step apart.
  EXPECT_LT(rounded_apart, samples / 500) << rounded_apart << " of " << samples;
}

TEST(SrgbEncoding, TheTwoSegmentsMeet) {
  const std::vector<float> k = shipped_coefficients();
  ASSERT_EQ(k.size(), 6u);
  const double linear_end = 12.92 * 0.0031308;
  EXPECT_NEAR(shader_power_segment(k, 0.0031308f), linear_end, 0.01 / 255);
  EXPECT_NEAR(shader_power_segment(k, 1.0f), 1.0, 0.01 / 255);
}

}  // namespace
}  // namespace systole::render
