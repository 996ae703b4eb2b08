#include "world/valves.h"

#include <algorithm>

namespace systole::world {

ValveMotion valve_motion(const mesh::Anatomy& anatomy, const std::vector<Eigen::Vector3d>& rest_positions,
                         const sim::Circulation& circulation) {
  ValveMotion motion;
  motion.cavities = anatomy.cavities;
  for (const mesh::Cavity& cavity : motion.cavities) motion.rest_volume_m3.push_back(mesh::cavity_volume(cavity, rest_positions));
  motion.volume_m3 = motion.previous_volume_m3 = motion.rest_volume_m3;
  for (const mesh::Valve& valve : anatomy.valves) {
    ValveMotion::Leaflets leaflets;
    leaflets.vertices = valve.vertices;
    leaflets.inflow = valve.opens_on_filling;
    leaflets.open_delta.resize(3, static_cast<Eigen::Index>(valve.vertices.size()));
    for (std::size_t i = 0; i < valve.vertices.size(); ++i) {
      leaflets.open_delta.col(static_cast<Eigen::Index>(i)) = valve.open_positions[i] - rest_positions[valve.vertices[i]];
    }
    for (std::size_t c = 0; c < motion.cavities.size(); ++c) {
      if (motion.cavities[c].name == valve.chamber) leaflets.cavity = static_cast<int>(c);
    }
    for (std::size_t c = 0; c < circulation.chambers.size(); ++c) {
      if (circulation.chambers[c].name == valve.chamber) leaflets.chamber = static_cast<int>(c);
    }
    motion.valves.push_back(std::move(leaflets));
  }
  return motion;
}

bool valve_open(sim::ChamberPhase phase, bool inflow) {
  return phase == (inflow ? sim::ChamberPhase::kFilling : sim::ChamberPhase::kEjection);
}

void update_valves(ValveMotion& motion, const Eigen::Matrix3Xd& positions, double frame_s,
                   const std::vector<sim::ChamberState>& chambers) {
  motion.previous_volume_m3.swap(motion.volume_m3);
  for (std::size_t c = 0; c < motion.cavities.size(); ++c) motion.volume_m3[c] = mesh::cavity_volume(motion.cavities[c], positions);
  for (ValveMotion::Leaflets& valve : motion.valves) {
    if (valve.chamber >= 0) {
      valve.opening = valve_open(chambers[static_cast<std::size_t>(valve.chamber)].phase, valve.inflow) ? 1.0 : 0.0;
      continue;
    }
    if (valve.cavity < 0) continue;
    const double full = 0.5 * motion.rest_volume_m3[valve.cavity];  // m^3/s
    const double flow = (motion.volume_m3[valve.cavity] - motion.previous_volume_m3[valve.cavity]) / frame_s;
    const double through = valve.inflow ? flow : -flow;
    // An outflow valve is held shut by the arterial pressure until the ventricle ejects: the
    // atria's contraction, which squeezes the ventricle slowly (a seventh of ejection's flow at
    // most), does not open it. Shut below `full`, fully open at twice that.
    const double shut = valve.inflow ? 0.05 * full : full, open = valve.inflow ? full : 2 * full;
    const double x = std::clamp((through - shut) / (open - shut), 0.0, 1.0);
    valve.opening = motion.measured ? x * x * (3 - 2 * x) : 0.0;
  }
  motion.measured = true;
}

void open_valves(const ValveMotion& motion, Eigen::Matrix3Xd& positions) {
  for (const ValveMotion::Leaflets& valve : motion.valves) {
    if (valve.opening == 0) continue;
    for (std::size_t i = 0; i < valve.vertices.size(); ++i) {
      positions.col(valve.vertices[i]) += valve.opening * valve.open_delta.col(static_cast<Eigen::Index>(i));
    }
  }
}

}  // namespace systole::world
