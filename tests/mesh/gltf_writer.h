#pragma once
// Writes small animated glTF 2.0 files (buffer embedded as base64) for the tests of
// mesh/animation and of training targets.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh.h"

namespace systole::mesh::testing {

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0) |
                       (i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0);
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[n & 63] : '=';
  }
  return out;
}

/// Appends raw values to a glTF buffer, 4-byte aligned; returns the view's "byteOffset,byteLength".
template <typename T>
std::pair<std::size_t, std::size_t> append(std::string& buffer, const std::vector<T>& values) {
  while (buffer.size() % 4 != 0) buffer.push_back('\0');
  const std::size_t offset = buffer.size();
  buffer.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  return {offset, values.size() * sizeof(T)};
}

enum class Motion { kMorph, kSkin };

/// A glTF 2.0 file (buffer embedded) of `m` animated over 1 s with keys at 0, 0.5 and 1 s:
/// kMorph: one morph target moving every vertex by 0.2 x its position, weight 0 -> 1 -> 0;
/// kSkin: every vertex bound to one joint translated (0, 0, 0) -> (0, 0.01, 0) -> (0, 0, 0).
inline void write_gltf(const std::filesystem::path& file, const TriangleMesh& m, Motion motion) {
  std::vector<float> positions, displacement;
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(1e9f), hi = -lo;
  for (const auto& p : m.positions) {
    for (int k = 0; k < 3; ++k) positions.push_back(float(p[k])), displacement.push_back(float(0.2 * p[k]));
    lo = lo.cwiseMin(p.cast<float>()), hi = hi.cwiseMax(p.cast<float>());
  }
  std::vector<std::uint32_t> indices;
  for (const auto& t : m.triangles) indices.insert(indices.end(), {std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])});
  const std::size_t n = m.positions.size();
  std::string buffer;
  std::vector<std::pair<std::size_t, std::size_t>> views;
  views.push_back(append(buffer, positions));                                  // 0
  views.push_back(append(buffer, indices));                                    // 1
  views.push_back(append(buffer, std::vector<float>{0.0f, 0.5f, 1.0f}));       // 2: key times
  if (motion == Motion::kMorph) {
    views.push_back(append(buffer, displacement));                             // 3
    views.push_back(append(buffer, std::vector<float>{0.0f, 1.0f, 0.0f}));     // 4: weights
  } else {
    views.push_back(append(buffer, std::vector<std::uint8_t>(4 * n, 0)));      // 3: joints
    std::vector<float> weights;
    for (std::size_t i = 0; i < n; ++i) weights.insert(weights.end(), {1.0f, 0.0f, 0.0f, 0.0f});
    views.push_back(append(buffer, weights));                                  // 4
    views.push_back(append(buffer, std::vector<float>{0, 0, 0, 0, 0.01f, 0, 0, 0, 0}));  // 5: translations
    std::vector<float> identity(16, 0.0f);
    for (int k = 0; k < 4; ++k) identity[k * 5] = 1.0f;
    views.push_back(append(buffer, identity));                                 // 6: inverse bind
  }
  std::string json = R"({"asset":{"version":"2.0"},"scene":0,)";
  json += R"("buffers":[{"byteLength":)" + std::to_string(buffer.size()) + R"(,"uri":"data:application/octet-stream;base64,)" + base64(buffer) + R"("}],)";
  json += R"("bufferViews":[)";
  for (std::size_t i = 0; i < views.size(); ++i) {
    json += (i ? "," : "") + std::string(R"({"buffer":0,"byteOffset":)") + std::to_string(views[i].first) + R"(,"byteLength":)" +
            std::to_string(views[i].second) + "}";
  }
  auto vec3 = [](const Eigen::Vector3f& v) {
    return "[" + std::to_string(v.x()) + "," + std::to_string(v.y()) + "," + std::to_string(v.z()) + "]";
  };
  const std::string count = std::to_string(n);
  json += R"(],"accessors":[)";
  json += R"({"bufferView":0,"componentType":5126,"count":)" + count + R"(,"type":"VEC3","min":)" + vec3(lo - Eigen::Vector3f::Constant(1e-4f)) +
          R"(,"max":)" + vec3(hi + Eigen::Vector3f::Constant(1e-4f)) + "},";
  json += R"({"bufferView":1,"componentType":5125,"count":)" + std::to_string(indices.size()) + R"(,"type":"SCALAR"},)";
  json += R"({"bufferView":2,"componentType":5126,"count":3,"type":"SCALAR","min":[0],"max":[1]},)";
  if (motion == Motion::kMorph) {
    json += R"({"bufferView":3,"componentType":5126,"count":)" + count + R"(,"type":"VEC3","min":)" + vec3(0.2f * lo - Eigen::Vector3f::Constant(1e-4f)) +
            R"(,"max":)" + vec3(0.2f * hi + Eigen::Vector3f::Constant(1e-4f)) + "},";
    json += R"({"bufferView":4,"componentType":5126,"count":3,"type":"SCALAR"}],)";
    json += R"("meshes":[{"name":"ball","primitives":[{"attributes":{"POSITION":0},"indices":1,"targets":[{"POSITION":3}]}],"weights":[0]}],)";
    json += R"("nodes":[{"name":"ball","mesh":0}],"scenes":[{"nodes":[0]}],)";
    json += R"("animations":[{"channels":[{"sampler":0,"target":{"node":0,"path":"weights"}}],"samplers":[{"input":2,"output":4,"interpolation":"LINEAR"}]}]})";
  } else {
    json += R"({"bufferView":3,"componentType":5121,"count":)" + count + R"(,"type":"VEC4"},)";
    json += R"({"bufferView":4,"componentType":5126,"count":)" + count + R"(,"type":"VEC4"},)";
    json += R"({"bufferView":5,"componentType":5126,"count":3,"type":"VEC3"},)";
    json += R"({"bufferView":6,"componentType":5126,"count":1,"type":"MAT4"}],)";
    json += R"("meshes":[{"name":"ball","primitives":[{"attributes":{"POSITION":0,"JOINTS_0":3,"WEIGHTS_0":4},"indices":1}]}],)";
    json += R"("skins":[{"joints":[1],"inverseBindMatrices":6}],)";
    json += R"("nodes":[{"name":"ball","mesh":0,"skin":0},{"name":"bone"}],"scenes":[{"nodes":[0,1]}],)";
    json += R"("animations":[{"channels":[{"sampler":0,"target":{"node":1,"path":"translation"}}],"samplers":[{"input":2,"output":5,"interpolation":"LINEAR"}]}]})";
  }
  std::ofstream(file, std::ios::binary) << json;
}

/// One part of a multi-part glTF: a node holding a mesh of one or more primitives, each
/// with a material.
struct GltfPart {
  std::string node, mesh, material;
  std::vector<TriangleMesh> primitives;
};

/// A static glTF 2.0 file (buffer embedded) the way anatomical atlases are built: group
/// nodes (name, parts) over part nodes, and loose part nodes at the top.
inline void write_parts_gltf(const std::filesystem::path& file,
                             const std::vector<std::pair<std::string, std::vector<GltfPart>>>& groups,
                             const std::vector<GltfPart>& loose = {}) {
  std::string buffer, views, accessors, meshes, nodes, materials;
  std::vector<std::string> material_names;
  int view_count = 0, accessor_count = 0, mesh_count = 0, node_count = 0;
  auto add_view = [&](std::pair<std::size_t, std::size_t> range) {
    views += (view_count ? "," : "") + std::string(R"({"buffer":0,"byteOffset":)") + std::to_string(range.first) +
             R"(,"byteLength":)" + std::to_string(range.second) + "}";
    return view_count++;
  };
  auto material_of = [&](const std::string& name) {
    for (std::size_t i = 0; i < material_names.size(); ++i) {
      if (material_names[i] == name) return static_cast<int>(i);
    }
    material_names.push_back(name);
    return static_cast<int>(material_names.size() - 1);
  };
  auto add_part = [&](const GltfPart& part) {
    std::string primitives;
    for (const TriangleMesh& m : part.primitives) {
      std::vector<float> positions;
      Eigen::Vector3f lo = Eigen::Vector3f::Constant(1e9f), hi = -lo;
      for (const auto& p : m.positions) {
        for (int k = 0; k < 3; ++k) positions.push_back(float(p[k]));
        lo = lo.cwiseMin(p.cast<float>()), hi = hi.cwiseMax(p.cast<float>());
      }
      std::vector<std::uint32_t> indices;
      for (const auto& t : m.triangles) indices.insert(indices.end(), {std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])});
      const int position_view = add_view(append(buffer, positions)), index_view = add_view(append(buffer, indices));
      auto vec3 = [](const Eigen::Vector3f& v) {
        return "[" + std::to_string(v.x()) + "," + std::to_string(v.y()) + "," + std::to_string(v.z()) + "]";
      };
      accessors += (accessor_count ? "," : "") + std::string(R"({"bufferView":)") + std::to_string(position_view) +
                   R"(,"componentType":5126,"count":)" + std::to_string(m.positions.size()) + R"(,"type":"VEC3","min":)" +
                   vec3(lo) + R"(,"max":)" + vec3(hi) + "}";
      accessors += R"(,{"bufferView":)" + std::to_string(index_view) + R"(,"componentType":5125,"count":)" +
                   std::to_string(indices.size()) + R"(,"type":"SCALAR"})";
      primitives += (primitives.empty() ? "" : ",") + std::string(R"({"attributes":{"POSITION":)") +
                    std::to_string(accessor_count) + R"(},"indices":)" + std::to_string(accessor_count + 1) +
                    R"(,"material":)" + std::to_string(material_of(part.material)) + "}";
      accessor_count += 2;
    }
    meshes += (mesh_count ? "," : "") + std::string(R"({"name":")") + part.mesh + R"(","primitives":[)" + primitives + "]}";
    nodes += (node_count ? "," : "") + std::string(R"({"name":")") + part.node + R"(","mesh":)" + std::to_string(mesh_count) + "}";
    ++mesh_count;
    return node_count++;
  };
  std::string roots;
  for (const auto& [group, parts] : groups) {
    std::string children;
    for (const GltfPart& part : parts) children += (children.empty() ? "" : ",") + std::to_string(add_part(part));
    nodes += (node_count ? "," : "") + std::string(R"({"name":")") + group + R"(","children":[)" + children + "]}";
    roots += (roots.empty() ? "" : ",") + std::to_string(node_count++);
  }
  for (const GltfPart& part : loose) roots += (roots.empty() ? "" : ",") + std::to_string(add_part(part));
  for (std::size_t i = 0; i < material_names.size(); ++i) {
    materials += (i ? "," : "") + std::string(R"({"name":")") + material_names[i] + R"("})";
  }
  std::string json = R"({"asset":{"version":"2.0"},"scene":0,)";
  json += R"("buffers":[{"byteLength":)" + std::to_string(buffer.size()) +
          R"(,"uri":"data:application/octet-stream;base64,)" + base64(buffer) + R"("}],)";
  json += R"("bufferViews":[)" + views + R"(],"accessors":[)" + accessors + R"(],"materials":[)" + materials +
          R"(],"meshes":[)" + meshes + R"(],"nodes":[)" + nodes + R"(],"scenes":[{"nodes":[)" + roots + "]}]}";
  std::ofstream(file, std::ios::binary) << json;
}

}  // namespace systole::mesh::testing
