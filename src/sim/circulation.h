#pragma once
// The blood in the ventricles: what holds a ventricle's volume while both its valves are
// shut, and what it pushes against while it ejects. A ventricle goes round Wiggers'
// four phases (Wiggers 1915; Katz, "Physiology of the Heart", ch. 11):
//
//   filling ──(its volume falls: the inflow valve shuts)──▶ isovolumic contraction
//   isovolumic contraction ──(its pressure reaches the afterload: the outflow valve opens)──▶ ejection
//   ejection ──(the flow turns back: the outflow valve shuts)──▶ isovolumic relaxation
//   isovolumic relaxation ──(its pressure falls to the filling pressure: the inflow valve opens)──▶ filling
//
// While both valves are shut the blood, incompressible, keeps the cavity's volume: a
// constraint V(x) = V_shut on the body whose multiplier is the cavity's pressure. While it
// ejects the blood pushes the cavity's faces out with the afterload, the artery's pressure,
// which rises as the artery fills (a volume-elastance afterload). Nothing is keyed to
// the drive: the phases follow from the simulated volume and pressure. The solver
// (projective dynamics) enforces the constraint and applies the load; this module says
// what a chamber is, measures it and moves it through its phases.

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace systole::sim {

/// One ventricle's cavity as a closed surface over the body's particles: its lining (a
/// render-mesh surface embedded in the body) and a cap across each valve annulus. Each
/// surface point is a fixed weighted sum of particles plus an offset, so the volume's
/// gradient with respect to the particles is exact.
struct Chamber {
  std::string name;                        ///< "left_ventricle", ...
  std::vector<Eigen::Vector3i> triangles;  ///< Over the points; closed, outward (volume > 0).
  /// The caps across the inflow and the outflow annulus: ranges [first, last) of triangles.
  /// An open valve's cap carries no load: the blood's pressure there acts on the atrium or
  /// the artery beyond it, not on the ventricle.
  std::pair<int, int> inflow_cap{0, 0}, outflow_cap{0, 0};
  /// Where the chordae tendineae pull: the points of the papillary muscles' wall, and the
  /// share of the shut inflow valve's load they take from its annulus (0: all on the annulus).
  std::vector<int> chordae_points;
  double chordae_share = 0;
  std::vector<int> point_begin;            ///< Point p's terms: [point_begin[p], point_begin[p+1]).
  std::vector<int> term_particle;
  std::vector<double> term_weight;         ///< unit: 1
  Eigen::Matrix3Xd point_offset;           ///< unit: m
  double rest_m3 = 0;                      ///< The volume at rest. unit: m^3
  /// The pressure its outflow valve opens at and the ejecting cavity pushes against (the
  /// aortic or pulmonary pressure), on the body's own stiffness scale. unit: Pa
  double afterload_Pa = 0;
  /// How the outflow pressure rises with the volume ejected since the valve opened (the
  /// artery filling; Sunagawa et al. 1983's effective arterial elastance). unit: Pa/m^3
  double arterial_elastance_Pa_per_m3 = 0;

  int point_count() const { return static_cast<int>(point_begin.size()) - 1; }
};

/// The blood of a body's ventricles, and the pressures its valves open at.
struct Circulation {
  std::vector<Chamber> chambers;
  /// The pressure an inflow valve opens below (the atrial pressure). unit: Pa
  double filling_Pa = 0;

  bool enabled() const { return !chambers.empty(); }
};

enum class ChamberPhase { kFilling, kIsovolumicContraction, kEjection, kIsovolumicRelaxation };

/// A chamber's phase and measures, in sim::State.
struct ChamberState {
  ChamberPhase phase = ChamberPhase::kFilling;
  double volume_m3 = 0;     ///< At the last step's end. unit: m^3
  /// The flow into the cavity, smoothed over kFlowSmoothing_s so a step's vibration does not
  /// count as a contraction (and the phases do not depend on the step). unit: m^3/s
  double flow_m3_per_s = 0;
  double smallest_m3 = 0;   ///< The least volume since the outflow valve opened. unit: m^3
  double shut_m3 = 0;       ///< The volume its blood keeps while both valves are shut. unit: m^3
  double pressure_Pa = 0;   ///< The cavity's pressure at the last step (the multiplier, or the load). unit: Pa
};

/// The rate of volume loss, per rest volume, at which a filling ventricle's inflow valve
/// shuts: above the atria's slow squeeze of the ventricle, below the ventricle's own
/// contraction's. unit: 1/s
inline constexpr double kShuttingRate_per_s = 1.0;
/// The time over which a chamber's flow is smoothed. unit: s
inline constexpr double kFlowSmoothing_s = 0.01;
/// How far, per rest volume, an ejecting chamber's volume must rise from its least for the
/// flow to have turned back: well above a step's vibration, a tenth of a millilitre. unit: 1
inline constexpr double kBackflow = 1e-3;

/// Whether the phase holds the chamber's volume.
inline bool isovolumic(ChamberPhase phase) {
  return phase == ChamberPhase::kIsovolumicContraction || phase == ChamberPhase::kIsovolumicRelaxation;
}

/// The chamber's volume at particle positions x. unit: m^3
double chamber_volume(const Chamber& chamber, const Eigen::Matrix3Xd& x);

/// The chamber's volume (returned) and its gradient with respect to every particle into
/// `gradient` (3 x particles, zero where the chamber has no weight). unit: m^3, m^2
double chamber_volume(const Chamber& chamber, const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& gradient);

/// Adds the forces of `pressure_Pa` on the chamber's surface, all but the cap of the valve its
/// phase holds open, to `force` (3 x particles): each triangle's area-weighted normal, a
/// third to each corner, spread to the particles that carry it. unit: N
void add_pressure_load(const Chamber& chamber, ChamberPhase phase, const Eigen::Matrix3Xd& x, double pressure_Pa,
                       Eigen::Matrix3Xd& force);

/// Moves every chamber through its phases after a step of h seconds ended at positions x,
/// with the pressure the step found in each (state.pressure_Pa) - see the diagram above.
void advance_phases(const Circulation& circulation, const Eigen::Matrix3Xd& x, double h,
                    std::vector<ChamberState>& chambers);

}  // namespace systole::sim
