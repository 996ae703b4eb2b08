#include "export/gltf.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include <tiny_gltf.h>

#include "common/atomic_output.h"
#include "common/error.h"

namespace systole::exporter {
namespace {

constexpr int kArrayBuffer = TINYGLTF_TARGET_ARRAY_BUFFER;
constexpr int kElementArrayBuffer = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;

/// glTF colours are linear; the scene's are sRGB (IEC 61966-2-1).
double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

/// Appends data to the one buffer, each view 4-byte aligned (every component type here is
/// at most 4 bytes), and describes it.
class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) {
    model_.buffers.emplace_back();
  }

  /// A float VEC3 accessor over `v` (3 x n); with_bounds adds min and max per component.
  int vec3(const Eigen::Matrix3Xf& v, bool with_bounds, int target) {
    const int view = add_view(v.data(), sizeof(float) * static_cast<std::size_t>(v.size()), target);
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_VEC3;
    a.count = static_cast<std::size_t>(v.cols());
    if (with_bounds) {
      // The stored floats' own extremes (exact in JSON: a float is a double).
      for (int k = 0; k < 3; ++k) {
        a.minValues.push_back(v.cols() ? double(v.row(k).minCoeff()) : 0.0);
        a.maxValues.push_back(v.cols() ? double(v.row(k).maxCoeff()) : 0.0);
      }
    }
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  /// A float SCALAR accessor; with_bounds adds min and max (animation inputs need them).
  int scalars(const std::vector<float>& v, bool with_bounds) {
    const int view = add_view(v.data(), sizeof(float) * v.size(), 0);
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = v.size();
    if (with_bounds && !v.empty()) {
      a.minValues = {double(*std::min_element(v.begin(), v.end()))};
      a.maxValues = {double(*std::max_element(v.begin(), v.end()))};
    }
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  /// Triangle indices: 16-bit when every vertex fits, else 32-bit.
  int indices(const std::vector<std::uint32_t>& idx, int vertex_count) {
    tinygltf::Accessor a;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = idx.size();
    if (vertex_count <= 65535) {
      std::vector<std::uint16_t> shorts(idx.begin(), idx.end());
      a.bufferView = add_view(shorts.data(), sizeof(std::uint16_t) * shorts.size(), kElementArrayBuffer);
      a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    } else {
      a.bufferView = add_view(idx.data(), sizeof(std::uint32_t) * idx.size(), kElementArrayBuffer);
      a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    }
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

 private:
  int add_view(const void* data, std::size_t bytes, int target) {
    auto& buffer = model_.buffers.front().data;
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }

  tinygltf::Model& model_;
};

/// A material per region that has triangles (in region order), then the body's.
int add_material(tinygltf::Model& model, const std::string& name, const scene::Color& srgb, double opacity, bool two_sided) {
  tinygltf::Material m;
  m.name = name;
  m.pbrMetallicRoughness.baseColorFactor = {srgb_to_linear(srgb[0]), srgb_to_linear(srgb[1]), srgb_to_linear(srgb[2]),
                                            opacity};
  // Tissue: a dielectric, wet but not glossy.
  m.pbrMetallicRoughness.metallicFactor = 0;
  m.pbrMetallicRoughness.roughnessFactor = 0.5;
  if (opacity < 1) m.alphaMode = "BLEND";
  m.doubleSided = two_sided;
  model.materials.push_back(m);
  return static_cast<int>(model.materials.size()) - 1;
}

// Each region's triangles as glTF indices, and last the triangles of no region (the body).
std::vector<std::vector<std::uint32_t>> triangles_by_region(const OrganTrack& organ) {
  const int regions = static_cast<int>(organ.region_names.size());
  std::vector<std::vector<std::uint32_t>> groups(static_cast<std::size_t>(regions) + 1);
  for (const auto& t : organ.triangles) {
    const int r = triangle_region(organ, t);
    auto& g = groups[static_cast<std::size_t>(r < 0 ? regions : r)];
    for (int k = 0; k < 3; ++k) g.push_back(static_cast<std::uint32_t>(t[k]));
  }
  return groups;
}

// Weights key by key, every target's at each key (the layout glTF asks of weight outputs),
// played on the morph targets of the last node added.
void add_weights_channel(tinygltf::Model& model, BufferBuilder& buffers, const MorphAnimation& morph, int time_accessor,
                         tinygltf::Animation& animation) {
  std::vector<float> weights;
  weights.reserve(static_cast<std::size_t>(morph.weights.size()));
  for (Eigen::Index key = 0; key < morph.weights.rows(); ++key) {
    for (Eigen::Index k = 0; k < morph.weights.cols(); ++k) weights.push_back(morph.weights(key, k));
  }
  tinygltf::AnimationSampler sampler;
  sampler.input = time_accessor;
  sampler.output = buffers.scalars(weights, false);
  sampler.interpolation = "LINEAR";
  animation.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
  channel.target_node = static_cast<int>(model.nodes.size()) - 1;
  channel.target_path = "weights";
  animation.channels.push_back(channel);
}

void add_organ(tinygltf::Model& model, BufferBuilder& buffers, const OrganTrack& organ, const MorphAnimation& morph,
               int time_accessor, tinygltf::Animation& animation) {
  tinygltf::Mesh mesh;
  mesh.name = organ.name;
  const int position = buffers.vec3(morph.base_position_m, true, kArrayBuffer);
  const int normal = buffers.vec3(morph.base_normal, false, kArrayBuffer);
  std::vector<std::map<std::string, int>> targets;
  tinygltf::Value::Array names;
  for (int k = 0; k < morph.target_count(); ++k) {
    targets.push_back({{"POSITION", buffers.vec3(morph.position_delta_m[static_cast<std::size_t>(k)], true, kArrayBuffer)},
                       {"NORMAL", buffers.vec3(morph.normal_delta[static_cast<std::size_t>(k)], false, kArrayBuffer)}});
    names.emplace_back(morph.target_names[static_cast<std::size_t>(k)]);
  }
  // Primitives by region: every one shares the vertices and the targets.
  const int regions = static_cast<int>(organ.region_names.size());
  const std::vector<std::vector<std::uint32_t>> groups = triangles_by_region(organ);
  for (int r = 0; r <= regions; ++r) {
    const auto& g = groups[static_cast<std::size_t>(r)];
    if (g.empty()) continue;
    const bool body = r == regions;
    tinygltf::Primitive p;
    p.attributes = {{"POSITION", position}, {"NORMAL", normal}};
    p.indices = buffers.indices(g, organ.vertex_count());
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.material = add_material(model, organ.name + (body ? "" : "/" + organ.region_names[static_cast<std::size_t>(r)]),
                              body ? organ.body_color : organ.region_colors[static_cast<std::size_t>(r)],
                              organ.opacity, !organ.closed);
    p.targets = targets;
    mesh.primitives.push_back(p);
  }
  // Viewers that ignore the animation show the first key's shape.
  for (int k = 0; k < morph.target_count(); ++k) mesh.weights.push_back(double(morph.weights(0, k)));
  // Blender and three.js name the shape keys from this (a glTF convention, not the spec).
  tinygltf::Value::Object extras;
  extras["targetNames"] = tinygltf::Value(names);
  mesh.extras = tinygltf::Value(extras);
  model.meshes.push_back(mesh);

  tinygltf::Node node;
  node.name = organ.name;
  node.mesh = static_cast<int>(model.meshes.size()) - 1;
  model.nodes.push_back(node);
  model.scenes.front().nodes.push_back(static_cast<int>(model.nodes.size()) - 1);

  if (morph.target_count() == 0) return;  // Nothing moves: no curve to play.
  add_weights_channel(model, buffers, morph, time_accessor, animation);
}

}  // namespace

std::string gltf_bytes(const Recording& rec, const std::vector<MorphAnimation>& morphs, bool binary) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Systole " SYSTOLE_VERSION;
  model.scenes.emplace_back();
  model.scenes.front().name = rec.scene_name;
  model.defaultScene = 0;
  BufferBuilder buffers(model);
  tinygltf::Animation animation;
  animation.name = rec.scene_name + (rec.loop ? " (loop)" : "");
  // One clock for every organ: all morphs of a recording have the same keys.
  const int times = morphs.empty() ? -1 : buffers.scalars(morphs.front().key_times_s, true);
  for (std::size_t o = 0; o < rec.organs.size(); ++o) add_organ(model, buffers, rec.organs[o], morphs[o], times, animation);
  if (!animation.channels.empty()) model.animations.push_back(animation);
  model.buffers.front().data.resize((model.buffers.front().data.size() + 3) / 4 * 4, 0);

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, binary)) {
    throw Error(ExitCode::kInternal, "tinygltf could not serialize the glTF document");
  }
  return out.str();
}

void write_gltf(const std::filesystem::path& file, const Recording& rec, const std::vector<MorphAnimation>& morphs,
                bool binary) {
  write_file_atomically(file, gltf_bytes(rec, morphs, binary));
}

}  // namespace systole::exporter
