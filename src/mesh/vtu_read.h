#pragma once
// A ParaView time series as a training target: the .pvd that `systole export x.pvd` writes
// (export/vtk.h) and its .vtu frames, or the same series saved again by ParaView.
//
// .pvd, a VTK collection: <VTKFile type="Collection"><Collection> with one
//   <DataSet timestep="t" file="f.vtu"/> per frame, in time order; t in seconds, f relative
//   to the .pvd's folder.
// .vtu, one per frame: <VTKFile type="UnstructuredGrid" byte_order="LittleEndian|BigEndian"
//   header_type="UInt32|UInt64"><UnstructuredGrid>, one <Piece NumberOfPoints NumberOfCells>
//   per organ (the writer puts a comment with the organ's name before each), holding
//     <Points>     one DataArray of 3 components: the positions
//     <Cells>      DataArrays `connectivity`, `offsets`, `types`: triangles (VTK type 5);
//                  quads (9) and polygons (7) are fanned from their first corner
//     <PointData>  optionally `displacement` (3 components: position minus rest) and
//                  `region` (the vertex's region index, -1 the organ's body); others ignored
//   Each DataArray is format="binary" (base64 of a UInt32 or UInt64 byte count followed by
//   the values, as export/vtk.cpp writes) or format="ascii" (numbers separated by
//   whitespace, as ParaView saves with Data Mode "Ascii"), of any of VTK's numeric types
//   (Int8 .. UInt64, Float32, Float64). Not read: appended data and compressed arrays
//   (ParaView's defaults when saving; choose Data Mode Binary or Ascii, compression none).
//
// Inputs:  the .pvd and its frames. Outputs: an AnimatedSurface.
// See also: export/vtk.h (the writer), mesh/animated_surface.h, train/target.cpp.

#include <filesystem>

#include "mesh/animated_surface.h"

namespace systole::mesh {

/// Reads the series `pvd` lists, piece `piece` of every frame (-1: the only piece a frame
/// holds; a file of several organs needs its index, 0 for the first).
///   rest          the first frame's points minus its `displacement` when it has one (the
///                 recorded rest), else the first frame's points
///   triangles     the first frame's cells; every frame must have the same
///   parts         "region_<n>" for each region index n >= 0 the first frame's `region`
///                 holds, ascending; vertex_part indexes them, -1 for the body. Both empty
///                 without a `region` array.
///   times         each DataSet's timestep, as listed; in seconds.
///   duration      the last time plus the span between the last two (a single frame: its
///                 time). unit: s
/// Throws Error(kNoInput) for a missing .pvd or frame (naming both), Error(kDataError)
/// naming the file for: XML that does not parse, a document of another type, no frames,
/// times that are not finite or do not increase, several pieces and `piece` -1 (saying how
/// many there are and to choose one), a piece out of range, an array missing, of the wrong
/// size or count, unparsable, appended or compressed, a cell that is not a surface polygon
/// or points outside the piece, non-finite positions, and a frame whose point count or
/// cells differ from the first's.
AnimatedSurface read_vtu_series(const std::filesystem::path& pvd, int piece = -1);

}  // namespace systole::mesh
