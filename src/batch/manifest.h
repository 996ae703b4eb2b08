#pragma once
// Skip-if-done: a small JSON manifest beside each video records what made it, so a rerun
// (a retried scheduler task, a second pass over a batch) renders only what changed.
//
// Inputs:  the job's identity: Systole's version, the scene file's bytes and those of the
//          mesh files it names, the -D overrides in order, the frame selection, the bake.
// Outputs: <video>.json, written atomically after the video; up_to_date() compares.
//          A manifest is only ever replaced, never removed: a run that fails leaves the
//          earlier video and its manifest as they were.
// See also: app/batch.h (runs jobs), docs/batch.md (the manifest's fields).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace systole::batch {

/// Everything that decides "this job makes the same file as before".
struct JobIdentity {
  std::string scene_path;               ///< As given (for people; the hash decides).
  std::uint64_t scene_hash = 0;         ///< scene_content_hash().
  std::vector<std::string> overrides;   ///< -D key=value, in the order applied.
  std::string frames;                   ///< --frames text; empty: the whole clip.
  std::uint64_t bake_checksum = 0;      ///< --from-bake file's checksum; 0: simulated.

  /// One 64-bit key over every field and SYSTOLE_VERSION.
  std::uint64_t key() const;
};


/// <video>.json
std::filesystem::path manifest_path(const std::filesystem::path& video);

/// True when the video exists and its manifest names the same key, the video's size and
/// the checksum of its bytes. So a manifest vouches for one video only: one replaced by
/// hand, or a new video whose run died before its own manifest was written (the earlier
/// manifest is kept until then, so a failed run loses no record), is not taken for done.
bool up_to_date(const std::filesystem::path& video, const JobIdentity& job);

/// Writes the manifest atomically; call after the video is in place.
void write_manifest(const std::filesystem::path& video, const JobIdentity& job);

}  // namespace systole::batch
