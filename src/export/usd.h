#pragma once
// USD as text (.usda): a root Xform with one Mesh per organ, its triangles, per-face
// display colours (its regions', linear) and its points time-sampled at every frame
// (timeCodesPerSecond = the video's fps, metres, Y up), for usdview, Omniverse, Houdini and
// Blender's USD importer.
//
// Inputs:  a Recording. Outputs: the file, written atomically.
// See also: docs/export.md.

#include <filesystem>

#include "export/recording.h"

namespace systole::exporter {

void write_usda(const std::filesystem::path& file, const Recording& rec);

}  // namespace systole::exporter
