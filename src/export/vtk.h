#pragma once
// A ParaView time series: `<name>.pvd` (a VTK collection: each frame's time and file) and
// one VTU file per frame in the folder `<name>_frames/`, each holding every organ as a
// piece: the surface's triangles, its vertex positions, and per vertex
//   region        (Int32)   the region index, -1 for the organ's body
//   strain        (Float32) mean relative edge-length change against rest (mesh/strain.h,
//                           what color_by strain shows)
//   activation    (Float32) the vertex's region drive phi, 0 relaxed .. 1 contracted (what
//                           color_by activation shows)
//   displacement  (Float32 x3) position minus rest. unit: m
// Arrays are VTK's inline binary (base64 of a UInt32 byte count and the little-endian data).
// The frame folder is written under a temporary name and renamed when complete, then the
// .pvd is committed, so a reader never sees a series that points at missing frames.
//
// Inputs:  a Recording. Outputs: the .pvd and its folder of .vtu files.
// See also: scripts/check-exports (VTK's own reader), docs/export.md.

#include <filesystem>
#include <string>

#include "export/recording.h"

namespace systole::exporter {

/// One frame's VTU document.
std::string vtu_document(const Recording& rec, int frame);

/// Writes `file` (.pvd) and its frames; returns the frames' folder.
std::filesystem::path write_pvd(const std::filesystem::path& file, const Recording& rec);

}  // namespace systole::exporter
