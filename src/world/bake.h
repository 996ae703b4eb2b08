#pragma once
// Bake files: a clip's simulated render-mesh positions, every frame, so a long clip can be
// rendered by frame ranges on many machines without anyone simulating twice (frame k
// needs every step before it). docs/bake-format.md describes the bytes.
//
// Inputs:  a scene (bake_clip), or a bake file and the same scene (BakeReader).
// Outputs: <file>.bake written atomically: header, float64 positions per frame per organ,
//          FNV-1a 64 checksum. Positions are stored at full precision because the normals
//          are computed from them: a frame rendered from a bake is bit for bit the frame a
//          simulating render makes.
// The format lives beside the world so that everyone who reads or writes frames reaches it
// (world/frame_source.h replays a bake; clip, export and batch use it through that).
// See also: clip::bake_clip, clip::RenderRequest::from_bake, systole bake, scripts/render-segments.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "scene/scene.h"
#include "world/world.h"

namespace systole::world {

inline constexpr std::uint32_t kBakeFormatVersion = 1;

struct BakedOrgan {
  std::string name;
  int vertex_count = 0;  ///< Render-mesh vertices.
};

struct BakeInfo {
  double fps = 0;                 ///< unit: 1/s
  int frame_count = 0;
  std::uint64_t scene_hash = 0;   ///< scene_content_hash() of the scene baked (provenance).
  std::vector<BakedOrgan> organs;
};

/// Writes a bake as its frames arrive: the header when opened, then one frame at a time
/// (in order, every organ's render positions), then the checksum and the rename in commit().
/// Destroyed uncommitted, it leaves nothing (common/atomic_output.h).
class BakeWriter {
 public:
  /// Throws Error(kCannotCreate/kBusy) when the file cannot be written.
  BakeWriter(const std::filesystem::path& file, const scene::Scene& scene, const World& world);
  ~BakeWriter();
  BakeWriter(const BakeWriter&) = delete;
  BakeWriter& operator=(const BakeWriter&) = delete;

  /// Appends organ `organ`'s render positions of the next frame (organs in order). unit: m
  void write(const Eigen::Matrix3Xd& positions);
  /// Writes the checksum and renames the file into place. Throws Error(kIoError).
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class BakeReader {
 public:
  /// Opens a bake and verifies it whole (checksum, size, version). Throws Error(kNoInput)
  /// when missing, Error(kDataError) naming the file and the problem otherwise.
  explicit BakeReader(const std::filesystem::path& file);

  const BakeInfo& info() const { return info_; }
  std::uint64_t checksum() const { return checksum_; }

  /// Throws Error(kDataError) unless the bake fits this scene's world: the same frame rate
  /// and frame count, the same organs in the same order with the same vertex counts.
  void check_matches(const scene::Scene& scene, const World& world) const;

  /// The render-mesh positions of `organ` at `frame`. unit: m
  void read(int frame, int organ, Eigen::Matrix3Xd& positions);

 private:
  std::filesystem::path file_;
  std::ifstream in_;
  BakeInfo info_;
  std::uint64_t checksum_ = 0;
  std::streamoff payload_offset_ = 0;  ///< Where frame 0 starts. unit: byte
  std::vector<std::streamoff> organ_offset_;  ///< Within a frame. unit: byte
  std::streamoff frame_bytes_ = 0;     ///< unit: byte
};

}  // namespace systole::world
