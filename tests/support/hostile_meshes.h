#pragma once
// Mesh files made to break a reader: generated here, byte by byte, never downloaded. Used by
// the mesh bounds' unit tests (tests/mesh/file_bounds_test.cpp) and the hostile-input corpus
// (tests/hostile/). Each is a valid file in every respect but the one it attacks.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace systole::test {

inline void write_binary(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string le32(std::uint32_t v) {
  return {static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff), static_cast<char>((v >> 16) & 0xff),
          static_cast<char>((v >> 24) & 0xff)};
}

/// A binary glTF of one triangle (mesh 0, "heart") placed by the nodes of `nodes_json` (a
/// JSON array), the scene's roots `roots_json`.
inline std::string glb(const std::string& nodes_json, const std::string& roots_json) {
  std::string bin;
  for (const float f : {0.f, 0.f, 0.f, 0.01f, 0.f, 0.f, 0.f, 0.01f, 0.f}) bin.append(reinterpret_cast<const char*>(&f), 4);
  for (const std::uint16_t i : {0, 1, 2, 0}) bin.append(reinterpret_cast<const char*>(&i), 2);  // 3 + padding
  std::string json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":)" + roots_json + R"(}],"nodes":)" +
                     nodes_json +
                     R"(,"meshes":[{"name":"heart","primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
                     R"("buffers":[{"byteLength":44}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
                     R"({"buffer":0,"byteOffset":36,"byteLength":6}],"accessors":[{"bufferView":0,"componentType":5126,)"
                     R"("count":3,"type":"VEC3","min":[0,0,0],"max":[0.01,0.01,0]},)"
                     R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]})";
  while (json.size() % 4 != 0) json.push_back(' ');
  const auto total = static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size());
  return "glTF" + le32(2) + le32(total) + le32(static_cast<std::uint32_t>(json.size())) + "JSON" + json +
         le32(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
}

/// Nodes 0 -> 1 -> ... -> n-1, the last placing the mesh: a chain `n` deep.
inline std::string chain_nodes(int n) {
  std::string nodes = "[";
  for (int i = 0; i + 1 < n; ++i) nodes += R"({"children":[)" + std::to_string(i + 1) + "]},";
  return nodes + R"({"mesh":0}])";
}

/// `n` nodes side by side, each placing the mesh (instances), all roots.
inline std::string wide_nodes(int n, std::string* roots) {
  std::string nodes = "[";
  *roots = "[";
  for (int i = 0; i < n; ++i) {
    nodes += (i ? "," : "") + std::string(R"({"mesh":0,"translation":[)") + std::to_string(i) + ",0,0]}";
    *roots += (i ? "," : "") + std::to_string(i);
  }
  *roots += "]";
  return nodes + "]";
}

/// An OBJ grid of `side` x `side` vertices and its triangles; `tail` is appended as is.
inline std::string grid_obj(int side, const std::string& head = "", const std::string& tail = "") {
  std::string obj = head;
  char line[96];
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      std::snprintf(line, sizeof line, "v %g %g %g\n", 1e-3 * i, 1e-3 * j, 1e-4 * ((i * j) % 7));
      obj += line;
    }
  }
  for (int i = 0; i + 1 < side; ++i) {
    for (int j = 0; j + 1 < side; ++j) {
      const int a = i * side + j + 1;
      std::snprintf(line, sizeof line, "f %d %d %d\nf %d %d %d\n", a, a + 1, a + side, a + 1, a + side + 1, a + side);
      obj += line;
    }
  }
  return obj + tail;
}

}  // namespace systole::test
