// The valves of an anatomical heart (world/valves.h): opened by the flow through them, or by
// the ventricle's phase when it has blood, on a box-shaped ventricle whose volume is known.

#include "world/valves.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/box.h"

namespace systole::world {
namespace {

using sim::ChamberPhase;

constexpr double kSide = 0.04;         // The ventricle: a 4 cm cube. unit: m
constexpr double kFrame_s = 1.0 / 30;  // unit: s
constexpr int kMitralVertex = 8, kAorticVertex = 9, kOtherVertex = 10;

/// A ventricle lined by a cube's faces turned inward (into the blood), open at the top: its
/// one rim is the mitral annulus. The mitral and aortic leaflets are one vertex each above it.
struct Heart {
  mesh::Anatomy anatomy;
  std::vector<Eigen::Vector3d> rest;
  Eigen::Vector3d mitral_open_delta{0, 0, -0.006}, aortic_open_delta{0.002, 0, 0.005};
};

Heart heart() {
  Heart h;
  const test::Box box = test::box(kSide, kSide, kSide);
  for (int i = 0; i < 8; ++i) h.rest.push_back(box.corners.col(i));
  h.rest.push_back(Eigen::Vector3d(0.5 * kSide, 0.5 * kSide, kSide));  // mitral leaflet
  h.rest.push_back(Eigen::Vector3d(0.8 * kSide, 0.5 * kSide, kSide));  // aortic leaflet
  h.rest.push_back(Eigen::Vector3d(0.0, 0.0, 2 * kSide));             // belongs to no valve
  mesh::Cavity lv;
  lv.name = "left_ventricle";
  for (std::size_t t = 0; t < box.triangles.size(); ++t) {
    if (t / 2 == test::kTop) continue;
    const Eigen::Vector3i& f = box.triangles[t];
    lv.lining.emplace_back(f[0], f[2], f[1]);  // Into the blood.
  }
  mesh::find_rims(lv);
  h.anatomy.cavities.push_back(lv);
  h.anatomy.valves.push_back({"mitral_valve", "left_ventricle", true, {kMitralVertex}, {h.rest[kMitralVertex] + h.mitral_open_delta}});
  h.anatomy.valves.push_back({"aortic_valve", "left_ventricle", false, {kAorticVertex}, {h.rest[kAorticVertex] + h.aortic_open_delta}});
  return h;
}

/// The surface with the ventricle scaled about its floor's corner to `volume_m3` (leaflets
/// and the other vertex where they rest).
Eigen::Matrix3Xd surface_at(const Heart& h, double volume_m3) {
  Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(h.rest.size()));
  for (std::size_t i = 0; i < h.rest.size(); ++i) x.col(static_cast<Eigen::Index>(i)) = h.rest[i];
  x.leftCols(8) *= std::cbrt(volume_m3) / kSide;
  return x;
}

double opening(const ValveMotion& m, bool inflow) {
  for (const auto& v : m.valves) {
    if (v.inflow == inflow) return v.opening;
  }
  ADD_FAILURE() << "no valve";
  return -1;
}

/// The openings after one frame in which the ventricle's volume changes at `rate` rest volumes
/// a second (after a first, still frame that starts the measurement).
std::pair<double, double> openings_at_rate(double rate) {
  const Heart h = heart();
  ValveMotion m = valve_motion(h.anatomy, h.rest, sim::Circulation{});
  const double v0 = std::pow(kSide, 3);
  update_valves(m, surface_at(h, v0), kFrame_s, {});
  update_valves(m, surface_at(h, v0 * (1 + rate * kFrame_s)), kFrame_s, {});
  return {opening(m, true), opening(m, false)};
}

TEST(Valves, AValveOpensOnlyInThePhaseThatSendsBloodThroughIt) {
  EXPECT_TRUE(valve_open(ChamberPhase::kFilling, true));
  EXPECT_FALSE(valve_open(ChamberPhase::kFilling, false));
  EXPECT_TRUE(valve_open(ChamberPhase::kEjection, false));
  EXPECT_FALSE(valve_open(ChamberPhase::kEjection, true));
  for (ChamberPhase shut : {ChamberPhase::kIsovolumicContraction, ChamberPhase::kIsovolumicRelaxation}) {
    EXPECT_FALSE(valve_open(shut, true));
    EXPECT_FALSE(valve_open(shut, false));
  }
}

TEST(Valves, StartClosedWithTheLiningsRestVolume) {
  const Heart h = heart();
  const ValveMotion m = valve_motion(h.anatomy, h.rest, sim::Circulation{});
  ASSERT_FALSE(m.empty());
  ASSERT_EQ(m.valves.size(), 2u);
  ASSERT_EQ(m.rest_volume_m3.size(), 1u);
  // The lining closed by its rim's cap encloses the cube.
  EXPECT_NEAR(m.rest_volume_m3[0], std::pow(kSide, 3), 1e-15);
  for (const auto& v : m.valves) {
    EXPECT_EQ(v.opening, 0.0);
    EXPECT_EQ(v.cavity, 0);
    EXPECT_EQ(v.chamber, -1);  // No blood.
  }
  EXPECT_TRUE(m.valves[0].open_delta.col(0).isApprox(h.mitral_open_delta));
  EXPECT_TRUE(m.valves[1].open_delta.col(0).isApprox(h.aortic_open_delta));
}

TEST(Valves, TheFirstFrameHasNoFlowToOpenThem) {
  const Heart h = heart();
  ValveMotion m = valve_motion(h.anatomy, h.rest, sim::Circulation{});
  // Already much larger than at rest: no earlier frame of this clip to measure a flow from.
  update_valves(m, surface_at(h, 1.5 * std::pow(kSide, 3)), kFrame_s, {});
  EXPECT_EQ(opening(m, true), 0.0);
  EXPECT_EQ(opening(m, false), 0.0);
  EXPECT_TRUE(m.measured);
}

TEST(Valves, FastFillingOpensTheInflowValveOnly) {
  // Full open at half a rest volume a second.
  const auto [inflow, outflow] = openings_at_rate(0.6);
  EXPECT_DOUBLE_EQ(inflow, 1.0);
  EXPECT_EQ(outflow, 0.0);
}

TEST(Valves, FastEjectionOpensTheOutflowValveOnly) {
  // Full open at one rest volume a second out.
  const auto [inflow, outflow] = openings_at_rate(-1.2);
  EXPECT_EQ(inflow, 0.0);
  EXPECT_DOUBLE_EQ(outflow, 1.0);
}

TEST(Valves, TheAtriasSlowSqueezeDoesNotOpenTheOutflowValve) {
  // Below half a rest volume a second out, the arterial pressure holds the aortic valve shut.
  const auto [inflow, outflow] = openings_at_rate(-0.4);
  EXPECT_EQ(inflow, 0.0);
  EXPECT_EQ(outflow, 0.0);
}

TEST(Valves, AStillVentricleKeepsBothShut) {
  const auto [inflow, outflow] = openings_at_rate(0.0);
  EXPECT_EQ(inflow, 0.0);
  EXPECT_EQ(outflow, 0.0);
}

TEST(Valves, OpeningGrowsSmoothlyWithTheFlow) {
  // Between shut and fully open the opening rises with the flow, strictly.
  double last = -1;
  for (double rate = 0.03; rate <= 0.5; rate += 0.02) {
    const double inflow = openings_at_rate(rate).first;
    EXPECT_GT(inflow, last) << rate;
    EXPECT_GE(inflow, 0.0);
    EXPECT_LE(inflow, 1.0);
    last = inflow;
  }
  // Halfway between shut (a twentieth of full) and full it is half open (smoothstep).
  EXPECT_NEAR(openings_at_rate(0.5 * (0.025 + 0.5)).first, 0.5, 1e-6);
  last = -1;
  for (double rate = -0.52; rate >= -1.0; rate -= 0.04) {
    const double outflow = openings_at_rate(rate).second;
    EXPECT_GT(outflow, last) << rate;
    last = outflow;
  }
}

TEST(Valves, OpeningMovesOnlyTheLeafletsByTheirShareOfTheWay) {
  const Heart h = heart();
  ValveMotion m = valve_motion(h.anatomy, h.rest, sim::Circulation{});
  m.valves[0].opening = 0.25;  // mitral
  m.valves[1].opening = 0.0;   // aortic
  const Eigen::Matrix3Xd closed = surface_at(h, std::pow(kSide, 3));
  Eigen::Matrix3Xd x = closed;
  open_valves(m, x);
  EXPECT_TRUE(x.col(kMitralVertex).isApprox(closed.col(kMitralVertex) + 0.25 * h.mitral_open_delta));
  EXPECT_EQ(x.col(kAorticVertex), closed.col(kAorticVertex));
  EXPECT_EQ(x.col(kOtherVertex), closed.col(kOtherVertex));
  EXPECT_EQ(x.leftCols(8), closed.leftCols(8));
  // Fully open: the leaflet lies at its open place.
  m.valves[0].opening = 1.0;
  x = closed;
  open_valves(m, x);
  EXPECT_TRUE(x.col(kMitralVertex).isApprox(h.anatomy.valves[0].open_positions[0]));
}

TEST(Valves, WithBloodThePhaseDecidesNotTheFlow) {
  const Heart h = heart();
  sim::Circulation blood;
  blood.chambers.emplace_back();
  blood.chambers[0].name = "left_ventricle";
  ValveMotion m = valve_motion(h.anatomy, h.rest, blood);
  for (const auto& v : m.valves) EXPECT_EQ(v.chamber, 0);
  const double v0 = std::pow(kSide, 3);
  std::vector<sim::ChamberState> state(1);
  // The volume falls fast, as in ejection, but the phases say otherwise.
  const struct {
    ChamberPhase phase;
    double inflow, outflow;
  } cases[] = {{ChamberPhase::kFilling, 1, 0},
               {ChamberPhase::kIsovolumicContraction, 0, 0},
               {ChamberPhase::kEjection, 0, 1},
               {ChamberPhase::kIsovolumicRelaxation, 0, 0}};
  double v = v0;
  for (const auto& c : cases) {
    state[0].phase = c.phase;
    update_valves(m, surface_at(h, v *= 0.9), kFrame_s, state);
    EXPECT_EQ(opening(m, true), c.inflow) << static_cast<int>(c.phase);
    EXPECT_EQ(opening(m, false), c.outflow) << static_cast<int>(c.phase);
  }
}

TEST(Valves, AValveOfAnUnknownVentricleStaysShut) {
  Heart h = heart();
  h.anatomy.valves[0].chamber = "right_ventricle";  // No such cavity, no such blood.
  ValveMotion m = valve_motion(h.anatomy, h.rest, sim::Circulation{});
  EXPECT_EQ(m.valves[0].cavity, -1);
  const double v0 = std::pow(kSide, 3);
  update_valves(m, surface_at(h, v0), kFrame_s, {});
  update_valves(m, surface_at(h, 1.1 * v0), kFrame_s, {});
  EXPECT_EQ(m.valves[0].opening, 0.0);
}

}  // namespace
}  // namespace systole::world
