#include "mesh/gltf_read.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "common/base64.h"
#include "common/error.h"
#include "mesh/import.h"

namespace systole::mesh {
namespace {

using Json = nlohmann::json;

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw Error(ExitCode::kDataError, file.string() + ": " + what);
}

std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ExitCode::kNoInput, file.string() + ": cannot be read");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A glTF document and its buffers' bytes: a .glb's JSON and BIN chunks, or a .gltf with
/// its buffers in files beside it or in data: URIs (gltf_read.h says why not tinygltf).
struct Document {
  Json json;
  std::vector<std::string> buffers;
};

std::uint32_t u32(const std::string& b, std::size_t at) {
  std::uint32_t x = 0;
  std::memcpy(&x, b.data() + at, 4);
  return x;
}

Document load(const std::filesystem::path& file) {
  const std::string bytes = read_bytes(file);
  Document d;
  std::string bin;
  bool glb = bytes.size() >= 12 && bytes.compare(0, 4, "glTF") == 0;
  try {
    if (glb) {
      std::size_t at = 12;
      if (at + 8 > bytes.size()) fail(file, "the GLB file is cut short");
      const std::uint32_t json_length = u32(bytes, at);
      if (u32(bytes, at + 4) != 0x4E4F534Au || at + 8 + json_length > bytes.size()) fail(file, "the GLB's first chunk is not its JSON");
      d.json = Json::parse(bytes.substr(at + 8, json_length));
      at += 8 + json_length;
      if (at + 8 <= bytes.size() && u32(bytes, at + 4) == 0x004E4942u) {
        const std::uint32_t bin_length = u32(bytes, at);
        if (at + 8 + bin_length > bytes.size()) fail(file, "the GLB's binary chunk is cut short");
        bin = bytes.substr(at + 8, bin_length);
      }
    } else {
      d.json = Json::parse(bytes);
    }
  } catch (const Json::exception& e) {
    fail(file, std::string("cannot read as glTF (") + e.what() + ")");
  }
  const Json buffers = d.json.value("buffers", Json::array());
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    const std::string uri = buffers[i].value("uri", "");
    if (uri.empty()) {
      if (!glb || i != 0) fail(file, "buffer " + std::to_string(i) + " has no data");
      d.buffers.push_back(bin);
    } else if (uri.rfind("data:", 0) == 0) {
      const auto comma = uri.find(',');
      const auto decoded = comma == std::string::npos ? std::nullopt : base64_decode(std::string_view(uri).substr(comma + 1));
      if (!decoded) fail(file, "buffer " + std::to_string(i) + "'s data URI is not base64");
      d.buffers.push_back(*decoded);
    } else {
      d.buffers.push_back(read_bytes(file.parent_path() / uri));
    }
  }
  return d;
}

/// An accessor's bytes, element by element: checked against its buffer before any is read.
struct View {
  const unsigned char* data = nullptr;
  std::size_t stride = 0, count = 0;
  int component = 0;
};

const Json& item(const std::filesystem::path& file, const Json& json, const char* array, long index) {
  if (!json.contains(array) || index < 0 || static_cast<std::size_t>(index) >= json.at(array).size())
    fail(file, std::string(array) + " " + std::to_string(index) + " does not exist");
  return json.at(array).at(static_cast<std::size_t>(index));
}

View view(const std::filesystem::path& file, const Document& d, long index, std::size_t component_bytes, int components) {
  const Json& a = item(file, d.json, "accessors", index);
  if (a.contains("sparse")) fail(file, "accessor " + std::to_string(index) + " is sparse, which is not read");
  if (!a.contains("bufferView")) fail(file, "accessor " + std::to_string(index) + " has no buffer view");
  const Json& v = item(file, d.json, "bufferViews", a.at("bufferView").get<long>());
  const long buffer = v.value("buffer", -1L);
  if (buffer < 0 || static_cast<std::size_t>(buffer) >= d.buffers.size()) fail(file, "a buffer view has no buffer");
  const std::string& b = d.buffers[static_cast<std::size_t>(buffer)];
  const std::size_t element = component_bytes * static_cast<std::size_t>(components);
  View out{nullptr, v.value("byteStride", std::size_t{0}), a.value("count", std::size_t{0}), a.value("componentType", 0)};
  if (out.stride == 0) out.stride = element;
  const std::size_t start = v.value("byteOffset", std::size_t{0}) + a.value("byteOffset", std::size_t{0});
  const std::size_t end = out.count == 0 ? start : start + out.stride * (out.count - 1) + element;
  if (end > b.size() || end > v.value("byteOffset", std::size_t{0}) + v.value("byteLength", std::size_t{0}))
    fail(file, "accessor " + std::to_string(index) + " reaches past its buffer");
  out.data = reinterpret_cast<const unsigned char*>(b.data()) + start;
  return out;
}

constexpr int kFloat = 5126, kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125;

/// A float accessor of `components` per element.
std::vector<float> floats(const std::filesystem::path& file, const Document& d, long index, int components) {
  const View v = view(file, d, index, 4, components);
  if (v.component != kFloat) fail(file, "accessor " + std::to_string(index) + " is not of floats");
  std::vector<float> out(v.count * static_cast<std::size_t>(components));
  for (std::size_t i = 0; i < v.count; ++i) std::memcpy(&out[i * components], v.data + i * v.stride, 4 * static_cast<std::size_t>(components));
  return out;
}

std::vector<std::uint32_t> indices(const std::filesystem::path& file, const Document& d, long index) {
  const int type = item(file, d.json, "accessors", index).value("componentType", 0);
  const std::size_t bytes = type == kUnsignedByte ? 1 : type == kUnsignedShort ? 2 : 4;
  if (bytes == 4 && type != kUnsignedInt) fail(file, "indices of accessor " + std::to_string(index) + " are not unsigned");
  const View v = view(file, d, index, bytes, 1);
  std::vector<std::uint32_t> out(v.count);
  for (std::size_t i = 0; i < v.count; ++i) {
    std::uint32_t x = 0;
    std::memcpy(&x, v.data + i * v.stride, bytes);  // Little-endian, as glTF is.
    out[i] = x;
  }
  return out;
}

std::vector<double> numbers(const Json& node, const char* key) {
  std::vector<double> out;
  if (node.contains(key)) {
    for (const Json& x : node.at(key)) out.push_back(x.get<double>());
  }
  return out;
}

Eigen::Matrix4d local_matrix(const Json& n) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  const std::vector<double> matrix = numbers(n, "matrix"), t = numbers(n, "translation"), r = numbers(n, "rotation"),
                            s = numbers(n, "scale");
  if (matrix.size() == 16) {
    for (int i = 0; i < 16; ++i) m(i % 4, i / 4) = matrix[static_cast<std::size_t>(i)];  // Column-major.
    return m;
  }
  Eigen::Affine3d a = Eigen::Affine3d::Identity();
  if (t.size() == 3) a.translate(Eigen::Vector3d(t[0], t[1], t[2]));
  if (r.size() == 4) a.rotate(Eigen::Quaterniond(r[3], r[0], r[1], r[2]).normalized());
  if (s.size() == 3) a.scale(Eigen::Vector3d(s[0], s[1], s[2]));
  return a.matrix();
}

/// One mesh placed by one node: its vertices once (every primitive sharing them), its
/// morph displacements and where its weights come from.
struct Block {
  int node = 0, position = -1;
  std::size_t first = 0, count = 0;
  Eigen::Matrix4d placement;
  std::vector<std::vector<float>> displacement;  ///< Per morph target, 3 per vertex.
  std::vector<double> weights;                   ///< At rest (the mesh's or node's default).
};

/// The weights of a sampler at time t: linear, step, or a cubic spline's values linearly.
std::vector<double> weights_at(const std::vector<float>& times, const std::vector<float>& values, const std::string& interpolation,
                               std::size_t targets, double t) {
  const std::size_t keys = times.size();
  const bool spline = interpolation == "CUBICSPLINE";
  auto value = [&](std::size_t key, std::size_t k) {
    return double(values[(spline ? 3 * key + 1 : key) * targets + k]);  // A spline key: in-tangent, value, out-tangent.
  };
  std::size_t i = 0;
  while (i + 2 < keys && times[i + 1] <= t) ++i;
  double f = 0;
  if (keys > 1 && t > times[i]) f = std::min(1.0, (t - times[i]) / std::max(1e-12, double(times[i + 1] - times[i])));
  if (keys == 1 || t <= times[0]) i = 0, f = 0;
  if (interpolation == "STEP") f = f >= 1 ? 1 : 0;
  std::vector<double> w(targets);
  for (std::size_t k = 0; k < targets; ++k) w[k] = keys == 1 ? value(0, k) : (1 - f) * value(i, k) + f * value(i + 1, k);
  return w;
}

/// A block's vertices (placed, onto `rest`), morph displacements and default weights from its
/// first primitive.
void read_block(const std::filesystem::path& file, const Document& d, const Json& primitive, const std::vector<double>& defaults,
                const std::string& name, Block& b, std::vector<Eigen::Vector3d>& rest) {
  const std::vector<float> p = floats(file, d, b.position, 3);
  b.count = p.size() / 3;
  for (std::size_t v = 0; v < b.count; ++v) rest.push_back((b.placement * Eigen::Vector4d(p[3 * v], p[3 * v + 1], p[3 * v + 2], 1)).head<3>());
  for (const Json& target : primitive.value("targets", Json::array())) {
    b.displacement.push_back(target.contains("POSITION") ? floats(file, d, target.at("POSITION").get<long>(), 3)
                                                         : std::vector<float>(3 * b.count, 0.0f));
    if (b.displacement.back().size() != 3 * b.count) fail(file, "a morph target of mesh '" + name + "' has another vertex count");
  }
  b.weights.assign(b.displacement.size(), 0.0);
  for (std::size_t k = 0; k < b.weights.size() && k < defaults.size(); ++k) b.weights[k] = defaults[k];
}

/// Every mesh under the scene's nodes, placed by their static transforms: its vertices,
/// parts and triangles into `out`, one block per mesh and shared vertex set.
std::vector<Block> collect_blocks(const std::filesystem::path& file, const Document& d, AnimatedSurface& out) {
  const Json& json = d.json;
  std::vector<Block> blocks;
  const long scene = json.value("scene", 0L);
  std::vector<std::pair<long, Eigen::Matrix4d>> stack;  // Iterative: check_mesh_file bounded the graph.
  if (json.contains("scenes") && scene >= 0 && static_cast<std::size_t>(scene) < json.at("scenes").size()) {
    for (const Json& root : json.at("scenes").at(static_cast<std::size_t>(scene)).value("nodes", Json::array()))
      stack.push_back({root.get<long>(), Eigen::Matrix4d::Identity()});
  }
  while (!stack.empty()) {
    const auto [index, parent] = stack.back();
    stack.pop_back();
    const Json& node = item(file, json, "nodes", index);
    const Eigen::Matrix4d global = parent * local_matrix(node);
    const Json children = node.value("children", Json::array());
    for (auto c = children.rbegin(); c != children.rend(); ++c) stack.push_back({c->get<long>(), global});
    if (!node.contains("mesh")) continue;
    const long mesh_index = node.at("mesh").get<long>();
    const Json& mesh = item(file, json, "meshes", mesh_index);
    const std::string name = !mesh.value("name", "").empty() ? mesh.value("name", "") : node.value("name", "");
    int part = -1;
    if (!name.empty()) {
      const auto it = std::find(out.parts.begin(), out.parts.end(), name);
      part = static_cast<int>(it - out.parts.begin());
      if (it == out.parts.end()) out.parts.push_back(name);
    }
    std::map<long, std::size_t> block_of_position;  // Primitives sharing vertices share a block.
    for (const Json& primitive : mesh.value("primitives", Json::array())) {
      if (primitive.value("mode", 4) != 4) continue;  // Triangles only.
      const Json attributes = primitive.value("attributes", Json::object());
      if (!attributes.contains("POSITION")) continue;
      const long position = attributes.at("POSITION").get<long>();
      auto found = block_of_position.find(position);
      if (found == block_of_position.end()) {
        Block b{static_cast<int>(index), static_cast<int>(position), out.rest.size(), 0, global, {}, {}};
        read_block(file, d, primitive, node.contains("weights") ? numbers(node, "weights") : numbers(mesh, "weights"), name, b, out.rest);
        out.vertex_part.resize(out.rest.size(), part);
        found = block_of_position.emplace(position, blocks.size()).first;
        blocks.push_back(std::move(b));
      }
      const Block& b = blocks[found->second];
      std::vector<std::uint32_t> corner;
      if (primitive.contains("indices")) {
        corner = indices(file, d, primitive.at("indices").get<long>());
      } else {
        for (std::uint32_t v = 0; v < b.count; ++v) corner.push_back(v);
      }
      for (std::size_t i = 0; i + 2 < corner.size(); i += 3) {
        if (std::max({corner[i], corner[i + 1], corner[i + 2]}) >= b.count) fail(file, "a triangle of mesh '" + name + "' indexes past its vertices");
        out.triangles.emplace_back(static_cast<int>(b.first + corner[i]), static_cast<int>(b.first + corner[i + 1]),
                                   static_cast<int>(b.first + corner[i + 2]));
      }
    }
  }
  return blocks;
}

/// The keys a weights track holds over [start, start + span), when every track's keys there
/// are evenly spaced and alike (a sampled clip, as `systole export` and baked exports write):
/// sampling at them reads the file's own shapes, not blends between them. Else kDefaultSamples.
template <class Tracks>
int even_key_count(const Tracks& tracks, double start, double span) {
  const double tolerance = 1e-4 * span;
  int count = 0;
  for (const auto& [node, track] : tracks) {
    std::vector<float> in;
    for (float t : track.times) {
      if (t >= start - tolerance && t < start + span - tolerance) in.push_back(t);
    }
    const int n = static_cast<int>(in.size());
    if (n < 4 || (count != 0 && n != count) || std::abs(in.front() - start) > tolerance) return kDefaultSamples;
    for (int i = 1; i < n; ++i) {
      if (std::abs(double(in[static_cast<std::size_t>(i)]) - (start + span * i / n)) > tolerance) return kDefaultSamples;
    }
    count = n;
  }
  return count > 0 ? count : kDefaultSamples;
}

/// The length of a sampled clip that does not close on its first pose (`systole export
/// --encoding frames` of a scene that does not loop): its keys evenly spaced from 0 in every
/// track, it lasts one key interval past its last key, as a point cache of those frames does.
/// 0 for any other clip (a closed loop lasts to its last key).
template <class Tracks>
double open_clip_duration(const Tracks& tracks) {
  double duration = 0;
  for (const auto& [node, track] : tracks) {
    const std::size_t n = track.times.size();
    if (n < 2 || track.values.size() % n != 0 || track.interpolation == "CUBICSPLINE") return 0;
    const double step = track.times[1] - track.times[0];
    if (!(step > 0) || std::abs(track.times[0]) > 1e-4 * step) return 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (std::abs(track.times[i] - step * double(i)) > 1e-3 * step) return 0;
    }
    const std::size_t per_key = track.values.size() / n;
    const bool closed = std::equal(track.values.begin(), track.values.begin() + static_cast<long>(per_key),
                                   track.values.end() - static_cast<long>(per_key));
    if (closed) return 0;
    duration = std::max(duration, step * double(n));
  }
  return duration;
}

/// `samples` poses of the blocks over period `period` of the `cycles` the animation holds,
/// into `out` (its duration too); 0 samples: at its keys where they are even (even_key_count).
void sample_poses(const std::filesystem::path& file, const Document& d, const Json& animation, const std::vector<Block>& blocks,
                  int samples, int cycles, int period, AnimatedSurface& out) {
  const Json channels = animation.value("channels", Json::array()), samplers = animation.value("samplers", Json::array());
  // The weights' samplers per node, and the animation's length.
  struct Track {
    std::vector<float> times, values;
    std::string interpolation;
  };
  std::map<int, Track> track_of_node;
  for (const Json& channel : channels) {
    const long sampler = channel.value("sampler", -1L);
    if (sampler < 0 || static_cast<std::size_t>(sampler) >= samplers.size()) fail(file, "a channel has no sampler");
    const Json& s = samplers.at(static_cast<std::size_t>(sampler));
    Track t{floats(file, d, s.value("input", -1L), 1), floats(file, d, s.value("output", -1L), 1), s.value("interpolation", "LINEAR")};
    if (t.times.empty()) fail(file, "an animation sampler has no keys");
    out.duration = std::max(out.duration, double(t.times.back()));
    track_of_node[channel.at("target").value("node", -1)] = std::move(t);
  }
  out.duration = std::max(out.duration, open_clip_duration(track_of_node));
  if (!(out.duration > 0)) fail(file, "the animation has no duration");
  const double span = out.duration / std::max(1, cycles), start = span * std::clamp(period, 0, std::max(1, cycles) - 1);
  if (samples == 0) samples = even_key_count(track_of_node, start, span);
  for (int i = 0; i < samples; ++i) {
    const double t = start + span * double(i) / double(samples);
    std::vector<Eigen::Vector3d> pose = out.rest;
    for (const Block& b : blocks) {
      std::vector<double> w = b.weights;
      if (const auto track = track_of_node.find(b.node); track != track_of_node.end() && !w.empty()) {
        const Track& k = track->second;
        const std::size_t per_key = k.interpolation == "CUBICSPLINE" ? 3 * w.size() : w.size();
        if (k.values.size() != per_key * k.times.size()) fail(file, "the weights of mesh node " + std::to_string(b.node) + " do not match its morph targets");
        w = weights_at(k.times, k.values, k.interpolation, w.size(), t);
      }
      const Eigen::Matrix3d linear = b.placement.topLeftCorner<3, 3>();
      for (std::size_t v = 0; v < b.count; ++v) {
        Eigen::Vector3d disp = Eigen::Vector3d::Zero();
        for (std::size_t k = 0; k < w.size(); ++k) {
          if (w[k] != 0) disp += w[k] * Eigen::Vector3d(b.displacement[k][3 * v], b.displacement[k][3 * v + 1], b.displacement[k][3 * v + 2]);
        }
        pose[b.first + v] += linear * disp;
      }
    }
    out.times.push_back(t);
    out.poses.push_back(std::move(pose));
  }
}

}  // namespace

std::optional<AnimatedSurface> read_gltf_morphs(const std::filesystem::path& file, int samples, int cycles, int period) {
  check_mesh_file(file);
  try {
    const Document d = load(file);
    const Json& json = d.json;
    if (!json.contains("animations") || json.at("animations").empty()) fail(file, "the file holds no animation");
    const Json& animation = json.at("animations").at(0);
    for (const Json& channel : animation.value("channels", Json::array())) {
      if (channel.value("target", Json::object()).value("path", "") != "weights") return std::nullopt;  // Nodes move: assimp's skinning.
    }
    AnimatedSurface out;
    out.file = file.string();
    const std::vector<Block> blocks = collect_blocks(file, d, out);
    if (out.parts.empty()) out.vertex_part.clear();
    const bool morphs = std::any_of(blocks.begin(), blocks.end(), [](const Block& b) { return !b.displacement.empty(); });
    if (!morphs) return std::nullopt;

    sample_poses(file, d, animation, blocks, samples, cycles, period, out);
    return out;
  } catch (const Json::exception& e) {
    fail(file, std::string("cannot read as glTF (") + e.what() + ")");
  }
}

}  // namespace systole::mesh
