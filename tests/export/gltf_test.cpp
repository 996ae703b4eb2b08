// glTF: the GLB container and the accessors as the specification requires them, frames
// reproduced to float32 rounding, the compact loop within its budget and closed.

#include <gtest/gtest.h>

#include <cstring>
#include <tiny_gltf.h>

#include "common/error.h"
#include "export/gltf.h"
#include "export/morph.h"
#include "recording_fixture.h"
#include "sim/motion_error.h"

namespace systole::test {
namespace {

std::uint32_t le32(const std::string& b, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

tinygltf::Model parse_glb(const std::string& bytes) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<unsigned>(bytes.size()));
  EXPECT_TRUE(ok) << err;
  EXPECT_TRUE(err.empty()) << err;
  return model;
}

/// An accessor's floats (tightly packed, as the writer lays them out).
std::vector<float> floats(const tinygltf::Model& m, int accessor) {
  const auto& a = m.accessors[static_cast<std::size_t>(accessor)];
  const auto& view = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const int comps = a.type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
  std::vector<float> out(a.count * comps);
  std::memcpy(out.data(), m.buffers[0].data.data() + view.byteOffset + a.byteOffset, sizeof(float) * out.size());
  return out;
}

Eigen::Matrix3Xd as_matrix(const std::vector<float>& v) {
  return Eigen::Map<const Eigen::Matrix3Xf>(v.data(), 3, static_cast<Eigen::Index>(v.size() / 3)).cast<double>();
}

/// The shapes a viewer computes at every key, from the file's own bytes.
sim::Trajectory shapes_from_file(const tinygltf::Model& m) {
  const auto& prim = m.meshes[0].primitives[0];
  const Eigen::Matrix3Xd base = as_matrix(floats(m, prim.attributes.at("POSITION")));
  const auto& sampler = m.animations[0].samplers[0];
  const std::vector<float> w = floats(m, sampler.output);
  const std::size_t targets = prim.targets.size();
  const std::size_t keys = w.size() / targets;
  std::vector<Eigen::Matrix3Xd> deltas;
  for (const auto& t : prim.targets) deltas.push_back(as_matrix(floats(m, t.at("POSITION"))));
  sim::Trajectory out;
  for (std::size_t k = 0; k < keys; ++k) {
    Eigen::Matrix3Xd x = base;
    for (std::size_t j = 0; j < targets; ++j) x += double(w[k * targets + j]) * deltas[j];
    out.push_back(x);
  }
  return out;
}

TEST(Glb, ChunksAndAccessorsAreAsTheSpecificationRequires) {
  const auto rec = beating_sphere();
  const auto morphs = std::vector{exporter::compact_morph(rec.organs[0], rec, {})};
  const std::string glb = exporter::gltf_bytes(rec, morphs, true);
  ASSERT_GT(glb.size(), 28u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(le32(glb, 4), 2u) << "container version";
  EXPECT_EQ(le32(glb, 8), glb.size()) << "the header's length is the file's";
  const std::uint32_t json_length = le32(glb, 12);
  EXPECT_EQ(le32(glb, 16), 0x4E4F534Au) << "first chunk JSON";
  EXPECT_EQ(json_length % 4, 0u);
  const std::size_t bin_at = 20 + json_length;
  ASSERT_LE(bin_at + 8, glb.size());
  const std::uint32_t bin_length = le32(glb, bin_at);
  EXPECT_EQ(le32(glb, bin_at + 4), 0x004E4942u) << "second chunk BIN";
  EXPECT_EQ(bin_length % 4, 0u);
  EXPECT_EQ(bin_at + 8 + bin_length, glb.size()) << "two chunks fill the file";

  const tinygltf::Model m = parse_glb(glb);
  ASSERT_EQ(m.meshes.size(), 1u);
  const int vertices = rec.organs[0].vertex_count();
  EXPECT_EQ(m.meshes[0].primitives.size(), 2u) << "one primitive per region";
  std::size_t indices = 0;
  for (const auto& p : m.meshes[0].primitives) {
    EXPECT_EQ(m.accessors[static_cast<std::size_t>(p.attributes.at("POSITION"))].count, std::size_t(vertices));
    EXPECT_EQ(p.targets.size(), std::size_t(morphs[0].target_count()));
    indices += m.accessors[static_cast<std::size_t>(p.indices)].count;
  }
  EXPECT_EQ(indices, 3 * rec.organs[0].triangles.size()) << "every triangle in one primitive";
  // Every POSITION accessor (base and targets) carries min and max, equal to its data's.
  int checked = 0;
  for (const auto& t : m.meshes[0].primitives[0].targets) {
    for (int accessor : {t.at("POSITION"), m.meshes[0].primitives[0].attributes.at("POSITION")}) {
      const auto& a = m.accessors[static_cast<std::size_t>(accessor)];
      ASSERT_EQ(a.minValues.size(), 3u);
      ASSERT_EQ(a.maxValues.size(), 3u);
      const Eigen::Matrix3Xd x = as_matrix(floats(m, accessor));
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(a.minValues[static_cast<std::size_t>(k)], x.row(k).minCoeff());
        EXPECT_EQ(a.maxValues[static_cast<std::size_t>(k)], x.row(k).maxCoeff());
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
  // The animation: times with min/max, weights = keys x targets.
  ASSERT_EQ(m.animations.size(), 1u);
  const auto& s = m.animations[0].samplers[0];
  const auto& input = m.accessors[static_cast<std::size_t>(s.input)];
  EXPECT_EQ(input.count, std::size_t(rec.frame_count() + 1));
  EXPECT_EQ(input.minValues.size(), 1u);
  EXPECT_EQ(input.maxValues.size(), 1u);
  EXPECT_EQ(m.accessors[static_cast<std::size_t>(s.output)].count, input.count * morphs[0].target_count());
  EXPECT_EQ(m.animations[0].channels[0].target_path, "weights");
}

TEST(Glb, TheFramesEncodingReproducesEveryFrameToFloatRounding) {
  const auto rec = beating_sphere(12, false);
  const std::string glb = exporter::gltf_bytes(rec, {exporter::frames_morph(rec.organs[0], rec)}, true);
  const auto shapes = shapes_from_file(parse_glb(glb));
  ASSERT_EQ(shapes.size(), rec.organs[0].frames_m.size());
  double worst = 0;
  for (std::size_t f = 0; f < shapes.size(); ++f) {
    worst = std::max(worst, (shapes[f] - rec.organs[0].frames_m[f]).cwiseAbs().maxCoeff());
  }
  // Two float roundings (base and delta) of coordinates under 5 cm: a few 1e-9 m.
  EXPECT_LT(worst, 4 * 0.05 * std::ldexp(1.0, -24));
  EXPECT_GT(worst, 0) << "floats cannot hold these doubles exactly; a zero would mean the test compares nothing";
}

TEST(Glb, TheCompactLoopIsWithinItsBudgetAndCloses) {
  const auto rec = beating_sphere(30);
  for (double budget : {5.0, 2.0, 0.5}) {
    exporter::CompactOptions options;
    options.max_error_pct = budget;
    const auto morph = exporter::compact_morph(rec.organs[0], rec, options);
    // 4-16 principal components and the mean shape's target, held at 1 over the rest (the base).
    EXPECT_GE(morph.target_count(), 5);
    EXPECT_LE(morph.target_count(), 17);
    EXPECT_EQ(morph.base_position_m, rec.organs[0].rest_m.cast<float>()) << "the organ's rest is the file's base";
    EXPECT_TRUE((morph.weights.col(0).array() == 1.0f).all()) << "the mean shape at every key";
    const auto shapes = shapes_from_file(parse_glb(exporter::gltf_bytes(rec, {morph}, true)));
    ASSERT_EQ(shapes.size(), rec.organs[0].frames_m.size() + 1) << "a closing key after the last frame";
    sim::Trajectory frames(shapes.begin(), shapes.end() - 1);
    const double error = sim::error_pct_of_motion(frames, rec.organs[0].frames_m);
    EXPECT_LE(error, budget) << "from the file's own bytes";
    EXPECT_NEAR(error, morph.error_pct, 1e-3) << "the reported error is the file's";
    EXPECT_EQ(morph.weights.row(0), morph.weights.row(morph.weights.rows() - 1)) << "the loop closes exactly";
  }
}

TEST(Glb, AMotionTheTargetsCannotHoldIsRefusedWithTheErrorReached) {
  // Independent noise at every frame has as many components as frames.
  const auto rec = beating_sphere(40, true, 0.002);
  exporter::CompactOptions options;
  options.max_error_pct = 0.1;
  try {
    exporter::compact_morph(rec.organs[0], rec, options);
    FAIL() << "no 16 targets hold 40 frames of noise within 0.1 %";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("16 morph targets"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--max-error"), std::string::npos) << e.what();
  }
}

TEST(Glb, TheCompactEncodingNeedsALoop) {
  const auto rec = beating_sphere(24, false);
  EXPECT_THROW(exporter::compact_morph(rec.organs[0], rec, {}), Error);
}

TEST(Glb, TheSameRecordingGivesTheSameBytes) {
  const auto rec = beating_sphere();
  const auto a = exporter::gltf_bytes(rec, {exporter::compact_morph(rec.organs[0], rec, {})}, true);
  const auto b = exporter::gltf_bytes(rec, {exporter::compact_morph(rec.organs[0], rec, {})}, true);
  EXPECT_EQ(a, b);
  const auto text = exporter::gltf_bytes(rec, {exporter::compact_morph(rec.organs[0], rec, {})}, false);
  EXPECT_NE(text.find("\"targetNames\""), std::string::npos);
  EXPECT_NE(text.find("data:application/octet-stream;base64,"), std::string::npos) << "a .gltf carries its buffer inline";
}

}  // namespace
}  // namespace systole::test
