#include "scene/content_hash.h"

#include <filesystem>
#include <fstream>

#include "common/error.h"
#include "common/hash.h"

namespace systole::scene {
namespace {

void hash_file(Fnv1a64& hash, const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ExitCode::kNoInput, "cannot read '" + file.string() + "'");
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) hash.update(buf, static_cast<std::size_t>(in.gcount()));
}

}  // namespace

std::uint64_t scene_content_hash(const Scene& scene) {
  Fnv1a64 hash;
  hash_file(hash, scene.path);
  for (const auto& organ : scene.organs) {
    if (!organ.mesh.file.empty()) hash_file(hash, organ.mesh.file);
  }
  return hash.value();
}

}  // namespace systole::scene
