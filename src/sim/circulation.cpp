#include "sim/circulation.h"

#include <Eigen/Geometry>
#include <algorithm>

#include "sim/constraints/volume.h"

namespace systole::sim {
namespace {

Eigen::Matrix3Xd points_at(const Chamber& chamber, const Eigen::Matrix3Xd& x) {
  Eigen::Matrix3Xd points = chamber.point_offset;
  for (int p = 0; p < chamber.point_count(); ++p) {
    for (int t = chamber.point_begin[p]; t < chamber.point_begin[p + 1]; ++t) {
      points.col(p) += chamber.term_weight[t] * x.col(chamber.term_particle[t]);
    }
  }
  return points;
}

}  // namespace

double chamber_volume(const Chamber& chamber, const Eigen::Matrix3Xd& x) {
  return enclosed_volume(points_at(chamber, x), chamber.triangles);
}

double chamber_volume(const Chamber& chamber, const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& gradient) {
  const Eigen::Matrix3Xd points = points_at(chamber, x);
  Eigen::Matrix3Xd point_gradient(3, points.cols());
  const double volume = volume_and_gradient(points, chamber.triangles, point_gradient);
  gradient.setZero(3, x.cols());
  for (int p = 0; p < chamber.point_count(); ++p) {
    for (int t = chamber.point_begin[p]; t < chamber.point_begin[p + 1]; ++t) {
      gradient.col(chamber.term_particle[t]) += chamber.term_weight[t] * point_gradient.col(p);
    }
  }
  return volume;
}

void add_pressure_load(const Chamber& chamber, ChamberPhase phase, const Eigen::Matrix3Xd& x, double pressure_Pa,
                       Eigen::Matrix3Xd& force) {
  const Eigen::Matrix3Xd points = points_at(chamber, x);
  Eigen::Matrix3Xd point_force = Eigen::Matrix3Xd::Zero(3, points.cols());
  const std::pair<int, int> open = phase == ChamberPhase::kFilling   ? chamber.inflow_cap
                                   : phase == ChamberPhase::kEjection ? chamber.outflow_cap
                                                                      : std::pair<int, int>{0, 0};
  // A shut inflow valve's leaflets hang on the chordae: their share of its load pulls the
  // papillary muscles' wall towards the base instead of pushing the annulus.
  const bool chordae = phase != ChamberPhase::kFilling && !chamber.chordae_points.empty();
  Eigen::Vector3d chordae_force = Eigen::Vector3d::Zero();
  for (int t = 0; t < static_cast<int>(chamber.triangles.size()); ++t) {
    if (t >= open.first && t < open.second) continue;
    const Eigen::Vector3i& tri = chamber.triangles[static_cast<std::size_t>(t)];
    Eigen::Vector3d third = (pressure_Pa / 6.0) * (points.col(tri[1]) - points.col(tri[0])).cross(points.col(tri[2]) - points.col(tri[0]));
    if (chordae && t >= chamber.inflow_cap.first && t < chamber.inflow_cap.second) {
      chordae_force += 3 * chamber.chordae_share * third;
      third *= 1 - chamber.chordae_share;
    }
    for (int k = 0; k < 3; ++k) point_force.col(tri[k]) += third;
  }
  for (int p : chamber.chordae_points) point_force.col(p) += chordae_force / static_cast<double>(chamber.chordae_points.size());
  for (int p = 0; p < chamber.point_count(); ++p) {
    for (int t = chamber.point_begin[p]; t < chamber.point_begin[p + 1]; ++t) {
      force.col(chamber.term_particle[t]) += chamber.term_weight[t] * point_force.col(p);
    }
  }
}

void advance_phases(const Circulation& circulation, const Eigen::Matrix3Xd& x, double h,
                    std::vector<ChamberState>& chambers) {
  for (std::size_t c = 0; c < chambers.size(); ++c) {
    const Chamber& chamber = circulation.chambers[c];
    ChamberState& s = chambers[c];
    const double volume = chamber_volume(chamber, x);
    const double flow = (volume - s.volume_m3) / h;  // Into the cavity. unit: m^3/s
    s.flow_m3_per_s += std::min(1.0, h / kFlowSmoothing_s) * (flow - s.flow_m3_per_s);
    s.volume_m3 = volume;
    switch (s.phase) {
      case ChamberPhase::kFilling:
        if (-s.flow_m3_per_s > kShuttingRate_per_s * chamber.rest_m3) {
          s.phase = ChamberPhase::kIsovolumicContraction;
          s.shut_m3 = volume;
        }
        break;
      case ChamberPhase::kIsovolumicContraction:
        if (s.pressure_Pa >= chamber.afterload_Pa) {
          s.phase = ChamberPhase::kEjection;
          s.smallest_m3 = volume;
        }
        break;
      case ChamberPhase::kEjection:
        // Blood turning back shuts the outflow valve: the volume rising from its least, by
        // more than a step's vibration.
        s.smallest_m3 = std::min(s.smallest_m3, volume);
        if (volume > s.smallest_m3 + kBackflow * chamber.rest_m3) {
          s.phase = ChamberPhase::kIsovolumicRelaxation;
          s.shut_m3 = volume;
        }
        break;
      case ChamberPhase::kIsovolumicRelaxation:
        if (s.pressure_Pa <= circulation.filling_Pa) s.phase = ChamberPhase::kFilling;
        break;
    }
  }
}

}  // namespace systole::sim
