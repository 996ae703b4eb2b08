#pragma once
// Crumpling: a driven region whose surface folds over itself and stays folded. A body that
// cannot take the shape its drives ask for (an open atlas part with nothing to hold its
// volume, parts pulling against each other) buckles into a wrinkled lump while every
// spring keeps a sane length, so the divergence check (sim::diagnose) never sees it. This
// watches the render surface of each driven region for lasting folds.
//
// The band a region may use, whatever its drive: a drive scales rest lengths smoothly, so
// neighbouring triangles turn against each other by a few degrees at most; a fold turns a
// pair by more than kFoldAngle. A region is crumpled while more than kFoldedShare of its
// adjacent-triangle pairs are folded from their rest angle, and the run stops once that has
// lasted longer than one cycle of its drive (a snap or a poke may fold a patch briefly).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mesh/organ.h"
#include "scene/organ.h"

namespace systole::world {

inline constexpr double kFoldAngle_rad = 1.0471975511965976;  ///< 60 deg. unit: rad
inline constexpr double kFoldedShare = 0.05;                  ///< unit: 1
inline constexpr int kLooksPerCycle = 8;

class FoldWatch {
 public:
  FoldWatch() = default;
  /// Watches every driven, unpinned region of `organ` with at least one pair of adjacent
  /// triangles on `geometry`'s surface (whose rest positions are the rest shape).
  FoldWatch(const scene::Organ& organ, const mesh::OrganGeometry& geometry);

  /// Looks at the surface's positions at `time_s` (once a frame). Returns what is wrong
  /// once a region has stayed crumpled for longer than its cycle.
  std::optional<std::string> update(const Eigen::Matrix3Xd& positions, double time_s);

  /// The share of each watched region's pairs folded at the last update. unit: 1
  const std::vector<double>& folded_shares() const { return shares_; }

  /// Whether a look is due at `time_s`: kLooksPerCycle times a cycle of the fastest watched
  /// drive is enough to see a fold that lasts a cycle, and a frame of a big mesh is spared
  /// the rest (never, when no region is watched).
  bool due(double time_s) const { return !regions_.empty() && time_s >= next_look_s_; }

 private:
  struct Region {
    std::string name;
    double period_s = 1;
    std::vector<int> pairs;          ///< Indices into pairs_.
    double crumpled_since_s = -1;    ///< When it last became crumpled; -1: it is not.
  };
  std::vector<Region> regions_;
  std::vector<Eigen::Vector2i> pairs_;     ///< Adjacent triangles (indices into triangles_).
  std::vector<double> folded_below_cos_;   ///< Per pair: folded while the cosine between their normals is below this. unit: 1
  std::vector<Eigen::Vector3i> triangles_; ///< The triangles of some pair, each once.
  std::vector<Eigen::Vector3d> normals_;   ///< Per triangle, at the last update (reused: no allocation a frame).
  std::vector<double> shares_;
  std::string organ_;
  double look_every_s_ = 0;  ///< The fastest watched drive's period / kLooksPerCycle. unit: s
  double next_look_s_ = 0;   ///< When update is next due. unit: s
};

}  // namespace systole::world
