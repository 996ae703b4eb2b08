#pragma once
// The computed ECG written beside the video (docs/electrophysiology.md): for each organ with
// a conduction system, its twelve leads as CSV and EDF+, and a 12-lead sheet as a PNG still.

#include <filesystem>
#include <vector>

#include "world/world.h"

namespace systole::clip {

/// The files beside `video` for the organ named `organ` ("out/heart.mp4": out/heart.ecg.csv,
/// out/heart.edf, out/heart.ecg.png; with several such organs, "heart.<organ>.ecg.csv" ...).
struct EcgFiles {
  std::filesystem::path csv, edf, sheet;
};
EcgFiles ecg_files_beside(const std::filesystem::path& video, const std::string& organ, bool several);

/// Writes every excited organ's ECG over [0, clip_s), each file whole or not at all; returns
/// the files written.
std::vector<std::filesystem::path> write_ecg_outputs(const world::World& world, const std::filesystem::path& video,
                                                     double clip_s);

}  // namespace systole::clip
