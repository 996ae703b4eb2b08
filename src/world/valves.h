#pragma once
// The valves of an anatomical heart (mesh/anatomy.h) open as blood flows through them: an
// inflow valve (mitral, tricuspid) while its ventricle fills, an outflow valve (aortic,
// pulmonary) while it empties; closed otherwise. The flow is the ventricle's volume change
// between frames, measured on the simulated lining: nothing is keyed to the drive. A heart
// with blood (sim/circulation.h) opens them by its ventricles' phases instead: the pressure
// decides, and both valves stay shut while the ventricle's volume is held.

#include <Eigen/Core>
#include <vector>

#include "mesh/anatomy.h"
#include "sim/circulation.h"

namespace systole::world {

struct ValveMotion {
  struct Leaflets {
    std::vector<int> vertices;
    Eigen::Matrix3Xd open_delta;  ///< Open minus closed place of each vertex, at rest. unit: m
    int cavity = -1;              ///< The ventricle (index into the anatomy's cavities).
    bool inflow = true;
    int chamber = -1;             ///< The ventricle's blood (index into the circulation's chambers), or -1.
    double opening = 0;           ///< 0 closed .. 1 open.
  };
  std::vector<mesh::Cavity> cavities;
  std::vector<Leaflets> valves;
  std::vector<double> rest_volume_m3;  ///< Per cavity. unit: m^3
  /// Per cavity, at the last update and the one before it. unit: m^3
  std::vector<double> volume_m3, previous_volume_m3;
  bool measured = false;

  bool empty() const { return valves.empty(); }
};

/// The valves of `anatomy`, closed, with `rest_positions` the surface at rest (unit: m), and
/// the blood that opens them when `circulation` has it.
ValveMotion valve_motion(const mesh::Anatomy& anatomy, const std::vector<Eigen::Vector3d>& rest_positions,
                         const sim::Circulation& circulation);

/// Sets each valve's opening from the flow into or out of its ventricle since the last call,
/// `frame_s` earlier, with `positions` the surface now (valves closed). An inflow valve is
/// fully open at a flow of half the ventricle's rest volume a second (about a fifth of peak
/// ejection) and shut below a twentieth of that; an outflow valve, which the arterial
/// pressure holds shut until the ventricle ejects, is shut below that flow and fully open at
/// twice it (the atria's contraction squeezes the ventricle far more slowly).
/// A valve with blood behind it is open exactly while its ventricle's phase (`chambers`) lets
/// blood through it.
void update_valves(ValveMotion& valves, const Eigen::Matrix3Xd& positions, double frame_s,
                   const std::vector<sim::ChamberState>& chambers);

/// Whether a ventricle in `phase` lets blood through its inflow (or outflow) valve.
bool valve_open(sim::ChamberPhase phase, bool inflow);

/// Moves the leaflets of `positions` (valves closed) to their current opening. unit: m
void open_valves(const ValveMotion& valves, Eigen::Matrix3Xd& positions);

}  // namespace systole::world
