#pragma once
// Point caches for Blender (and Maya, 3ds Max, Houdini): the organ's vertex positions at
// every frame, applied to its rest mesh (an OBJ beside the cache) by Blender's Mesh Cache
// modifier or its MDD importer. One cache and one OBJ per organ (export/recording.h's
// organ_file names them when there are several).
//
// PC2 (pc2.cpp), as Blender's Mesh Cache reads it, little-endian:
//   char[12] "POINTCACHE2\0", int32 version 1, int32 points, float32 start frame,
//   float32 sample rate (frames between samples), int32 samples, then float32 x y z per
//   point per sample.
// MDD (mdd.cpp), big-endian: int32 frames, int32 points, float32 time of each frame (s),
//   then float32 x y z per point per frame.
// OBJ (obj.cpp): the rest mesh, vertices in the caches' order, metres, Y up.
//
// Inputs:  a Recording. Outputs: the files, each written atomically.
// See also: scripts/check-exports (Blender reads them back), docs/export.md.

#include <filesystem>

#include "export/recording.h"

namespace systole::exporter {

void write_pc2(const std::filesystem::path& file, const OrganTrack& organ);
void write_mdd(const std::filesystem::path& file, const OrganTrack& organ, double fps);
void write_obj(const std::filesystem::path& file, const OrganTrack& organ);

/// Writes each organ's cache (.pc2 or .mdd by `file`'s extension) and its rest mesh OBJ
/// beside it; returns the files written.
std::vector<std::filesystem::path> write_point_caches(const std::filesystem::path& file, const Recording& rec);

}  // namespace systole::exporter
