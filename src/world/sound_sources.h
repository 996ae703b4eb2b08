#pragma once
// What the soundtrack (docs/sound.md) reads from the simulation, measured after every
// solver step (frames are 33 ms apart; heart sounds must land within 10 ms):
//  - the ventricles' size, whose turning points time the heart sounds: S1 when they start
//    to shrink (the atrioventricular valves close as ventricular pressure rises), S2 when
//    they start to refill (the semilunar valves have closed), S3 at the peak of early
//    refilling. A heart with blood (sim/circulation.h) times S1 and S2 by its left
//    ventricle's valves instead (clip/soundtrack.cpp): with both valves shut between them,
//    the size turns before the mitral valve closes and after the aortic one does;
//  - an organ's enclosed volume, whose rate of change is the breath's air flow.
// The ventricles' size is a proxy that needs no closed cavity, so it works on any heart (the
// solid procedural heart, the anatomical heart's myocardium, a mesh file): the mean distance
// of the regions' particles from their centroid. Its turning points are those of the
// chamber volume wherever the wall moves with the cavity (the wall contracts about the
// chamber's centre), which is what the drives make the regions do.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sim/model.h"

namespace systole::world {

/// One value of a simulated signal at the end of a solver step.
struct Sample {
  double time_s = 0;  ///< Organ time. unit: s
  double value = 0;   ///< The signal (unit: the signal's).
};

/// The particles of some regions of a body, measured as one chamber.
class RegionSize {
 public:
  RegionSize() = default;
  /// The particles of `model` whose region is one of `regions` (indices into model.regions).
  RegionSize(const sim::Model& model, const std::vector<int>& regions);
  /// Mean distance of the particles from their centroid at positions `x`. unit: m
  double measure(const Eigen::Matrix3Xd& x) const;
  int particle_count() const { return static_cast<int>(particles_.size()); }

 private:
  std::vector<int> particles_;
};

enum class CycleEventKind {
  kSystoleStart,  ///< The ventricles start to contract, the atrioventricular valves close: S1.
  kSystoleEnd,    ///< Their ejection ends, the semilunar valves close: S2.
  kPeakRefill,   ///< Early refilling is fastest: S3.
};

struct CycleEvent {
  CycleEventKind kind = CycleEventKind::kSystoleStart;
  double time_s = 0;  ///< Organ time, between steps by parabolic interpolation. unit: s
};

/// The turning points of a chamber size sampled every step (uniform spacing): a maximum is
/// a shrink onset, a minimum a refill onset, each counted only when the size then moves away
/// by more than `hysteresis` of its range over the whole run (so the small ringing of a
/// mass-spring body near a plateau is not a beat), and placed between samples at the vertex of the parabola
/// through the extreme sample and its two neighbours. Between each refill onset and the next
/// shrink onset, the fastest growth is a peak refill. Events in time order.
std::vector<CycleEvent> detect_cycle_events(const std::vector<Sample>& size, double hysteresis = 0.2);

/// The time of the extremum of the parabola through samples i-1, i, i+1 (uniform spacing),
/// kept within half a step of sample i. unit: s
double parabolic_peak_s(const std::vector<Sample>& s, std::size_t i);

}  // namespace systole::world
