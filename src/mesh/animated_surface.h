#pragma once
// A surface animated over time, as a training target reads it from a file: its own rest
// mesh (in the file's units and frame, node transforms applied) and its vertices at poses
// over time. Every reader returns one, whatever the format; train/target.cpp aligns it to
// the organ and transfers its motion onto the organ's surface (train/transfer.h).
//
// Readers: mesh/animation.h (glTF/GLB, FBX, Collada... through assimp: morph targets and
// skinning), mesh/point_cache_read.h (PC2 or MDD with the OBJ beside it), mesh/vtu_read.h
// (a ParaView series: a .pvd listing .vtu files). Each format is what `systole export`
// writes, so export -> edit elsewhere -> tune is a round trip.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace systole::mesh {

/// Poses sampled over one period from an animation whose keys are not evenly spaced (an
/// animator's few keys, or a skeleton's): enough for the three harmonics training fits.
inline constexpr int kDefaultSamples = 32;

struct AnimatedSurface {
  std::vector<Eigen::Vector3d> rest;          ///< The file's rest vertices. unit: the file's
  std::vector<Eigen::Vector3i> triangles;     ///< Over `rest`, outward facing where the file says so.
  std::vector<std::string> parts;             ///< Named parts (nodes, groups, objects, pieces); may be empty.
  std::vector<int> vertex_part;               ///< Per vertex: its part in `parts`, -1 none; empty when `parts` is.
  std::vector<double> times;                  ///< Each pose's time, increasing. unit: s, or frames when !in_seconds
  std::vector<std::vector<Eigen::Vector3d>> poses;  ///< Each pose's vertices, in `rest`'s order. unit: the file's
  double duration = 0;                        ///< The animation's length (the last pose may end before it). unit: as times
  bool in_seconds = true;                     ///< False when the file counts frames, not seconds (PC2).
  std::string file;                           ///< For messages.
};

}  // namespace systole::mesh
