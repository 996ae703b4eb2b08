#pragma once
// Point caches as training targets: a PC2 or MDD file (what `systole export x.pc2` / `x.mdd`
// writes, and what Blender's Mesh Cache modifier, Maya, 3ds Max and Houdini read and write)
// with its rest mesh, the OBJ beside it. The cache holds only positions, one per `v` line of
// the OBJ in order, so the OBJ is read as written: no welding, no reordering.
//
// PC2, little-endian: char[12] "POINTCACHE2\0", int32 version (1), int32 points, float32
//   start frame, float32 sample rate (frames between samples), int32 samples, then float32
//   x y z per point per sample. No seconds: poses are timed in frames.
// MDD, big-endian: int32 frames, int32 points, float32 time of each frame (s), then float32
//   x y z per point per frame.
// OBJ: `v x y z` lines (further numbers, e.g. colours, ignored) and `f` lines of 3 or more
//   corners in any of the forms v, v/vt, v//vn, v/vt/vn, negative indices counting back from
//   the last `v` so far; a polygon is fanned into triangles from its first corner. `o` and
//   `g` lines name the part of the faces after them; everything else is ignored.
//
// Inputs:  the cache (and optionally the rest mesh's path). Outputs: an AnimatedSurface.
// See also: export/point_cache.h (the writers), mesh/animated_surface.h, train/target.cpp.

#include <filesystem>

#include "mesh/animated_surface.h"

namespace systole::mesh {

/// Reads `cache` (.pc2 or .mdd, by its extension) and its rest mesh `obj`, by default the
/// cache's path with the extension .obj (as `systole export` writes it: `heart.pc2` beside
/// `heart.obj`; `clip-heart.pc2` beside `clip-heart.obj` for one organ of several).
///   rest, triangles      the OBJ's `v` lines in order and its faces as triangles.
///   parts, vertex_part   the OBJ's `o`/`g` names, in order of first use; a vertex is in the
///                        part of the first face that uses it, -1 when no face does. Both
///                        empty when the OBJ names none.
///   times, in_seconds    PC2: start frame + k x sample rate, in frames (in_seconds false).
///                        MDD: each frame's time as written, in seconds.
///   duration             PC2: samples x sample rate. unit: frames
///                        MDD: the last time plus the span between the last two (a single
///                        frame: its time). unit: s
/// Throws Error(kNoInput) when the cache or the OBJ cannot be read (naming both for the
/// OBJ), Error(kDataError) naming the file for: an unknown extension, a PC2 without its
/// signature or of another version, no samples or no points, a file shorter or longer than
/// its header says (checked before anything is allocated for it), a cache whose point count
/// is not the OBJ's vertex count, a non-finite coordinate, time, start or a sample rate not
/// above zero, MDD times that do not increase, and an OBJ line that cannot be read (with its
/// line number).
AnimatedSurface read_point_cache(const std::filesystem::path& cache, const std::filesystem::path& obj = {});

}  // namespace systole::mesh
