// The conduction system on the anatomical heart and the ECG it makes: the pathway's order,
// and the normal 12-lead ECG's figures against their published ranges (study/physiology.h
// cites them: Surawicz et al. 2009 and Rautaharju et al. 2009, AHA/ACCF/HRS).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "electro/conduction.h"
#include "electro/ecg_measure.h"
#include "electro/leads.h"
#include "mesh/procedural/organs.h"

namespace systole::electro {
namespace {

struct Span {
  double first = 1e9, last = -1e9;
};

Span span(const Excitation& ex, Tissue tissue) {
  Span s;
  for (std::size_t i = 0; i < ex.tissue.size(); ++i) {
    if (ex.tissue[i] != tissue || std::isnan(ex.activation_s[i])) continue;
    s.first = std::min(s.first, ex.activation_s[i]);
    s.last = std::max(s.last, ex.activation_s[i]);
  }
  return s;
}

const mesh::OrganMesh& heart() {
  static const mesh::OrganMesh mesh = mesh::procedural::anatomical_heart(3);
  return mesh;
}

/// The second beat of three at 72 bpm, measured.
BeatMeasures beat_of(const Excitation& ex) {
  const double cycle = 60.0 / 72;
  const std::vector<double> beats = {0, cycle, 2 * cycle, 3 * cycle};
  const Ecg ecg = compute_ecg(heart(), ex, beats, 0, 3 * cycle, 500);
  return measure_beat(ecg, cycle - 0.02, 2 * cycle - 0.02, cycle);
}

const LeadWaves& lead(const BeatMeasures& b, const char* name) { return b.leads[static_cast<std::size_t>(lead_index(name))]; }

TEST(Conduction, ReachesEveryExcitableNodeAlongThePathway) {
  const Excitation ex = excite(heart(), {});
  const Span atria = span(ex, Tissue::kAtrium), ventricles = span(ex, Tissue::kVentricle);
  EXPECT_EQ(atria.first, 0.0);  // The sinus node fires the beat.
  EXPECT_GE(ex.av_node_s, atria.first);
  EXPECT_LE(ex.av_node_s, atria.last);
  // Nothing reaches the ventricles but through the AV node's delay and the His bundle.
  EXPECT_NEAR(ex.his_s - ex.av_node_s, ConductionParams{}.av_node_s, 1e-12);
  EXPECT_GT(ventricles.first, ex.his_s);
  // Normal ventricular activation takes about 80 ms (Durrer et al. 1970).
  EXPECT_GT(ventricles.last - ventricles.first, 0.06);
  EXPECT_LT(ventricles.last - ventricles.first, 0.11);
  int unreached = 0;
  for (std::size_t i = 0; i < ex.tissue.size(); ++i) unreached += ex.excitable(static_cast<int>(i)) && std::isnan(ex.activation_s[i]);
  EXPECT_EQ(unreached, 0);
}

TEST(Conduction, EndocardiumIsExcitedBeforeEpicardium) {
  const Excitation ex = excite(heart(), {});
  const mesh::Myocardium& m = heart().anatomy.myocardium;
  double lining = 0, outside = 0;
  int n_lining = 0, n_outside = 0;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (ex.tissue[i] != Tissue::kVentricle || m.node_wall[i] != 0 || m.node_along[i] < 0.3 * m.annulus_along) continue;
    if (m.node_depth[i] < 1e-9) lining += ex.activation_s[i], ++n_lining;
    if (m.node_depth[i] > 1 - 1e-9) outside += ex.activation_s[i], ++n_outside;
  }
  ASSERT_GT(n_lining, 0);
  ASSERT_GT(n_outside, 0);
  EXPECT_LT(lining / n_lining + 0.005, outside / n_outside);
}

TEST(Conduction, ABlockedBranchLeavesItsVentricleLate) {
  const Excitation normal = excite(heart(), {});
  ConductionParams left, right;
  left.block = Block::kLeftBundle;
  right.block = Block::kRightBundle;
  const Excitation lbbb = excite(heart(), left), rbbb = excite(heart(), right);
  const Span n = span(normal, Tissue::kVentricle), l = span(lbbb, Tissue::kVentricle), r = span(rbbb, Tissue::kVentricle);
  EXPECT_GT(l.last - l.first, n.last - n.first + 0.02);
  EXPECT_GT(r.last - r.first, n.last - n.first + 0.01);
}

TEST(Conduction, RestitutionShortensTheActionPotentialWithRate) {
  EXPECT_DOUBLE_EQ(action_potential_s(0.3, 1.0), 0.3);
  EXPECT_LT(action_potential_s(0.3, 0.5), action_potential_s(0.3, 0.8));
  EXPECT_NEAR(action_potential_s(0.3, 0.5), 0.3 * std::cbrt(0.5), 1e-12);
}

TEST(ComputedEcg, NormalSinusBeatHasNormalIntervalsAxisAndTransition) {
  const BeatMeasures b = beat_of(excite(heart(), {}));
  EXPECT_GE(b.pr_s, 0.120);
  EXPECT_LE(b.pr_s, 0.200);
  EXPECT_GE(b.qrs_s, 0.080);
  EXPECT_LE(b.qrs_s, 0.110);
  EXPECT_GE(b.qtc_s, 0.350);
  EXPECT_LE(b.qtc_s, 0.450);
  EXPECT_GE(b.axis_deg, -30);
  EXPECT_LE(b.axis_deg, 90);
  EXPECT_GE(b.transition, 2);
  EXPECT_LE(b.transition, 4);
}

TEST(ComputedEcg, NormalSinusBeatHasTheNormalPolarities) {
  const BeatMeasures b = beat_of(excite(heart(), {}));
  for (const char* name : {"I", "II", "V5", "V6"}) {
    EXPECT_GT(lead(b, name).r, lead(b, name).s) << "QRS positive in " << name;
  }
  EXPECT_GT(lead(b, "aVR").s, lead(b, "aVR").r) << "QRS negative in aVR";
  for (const char* name : {"I", "II", "V4", "V5", "V6"}) EXPECT_GT(lead(b, name).t, 0) << "T upright in " << name;
}

TEST(ComputedEcg, LeadsFollowEinthovenAndGoldberger) {
  const double cycle = 60.0 / 72;
  const Ecg ecg = compute_ecg(heart(), excite(heart(), {}), {0, cycle}, 0, cycle, 500);
  const auto& I = *ecg.lead("I");
  const auto& II = *ecg.lead("II");
  const auto& III = *ecg.lead("III");
  const auto& aVR = *ecg.lead("aVR");
  const auto& aVL = *ecg.lead("aVL");
  const auto& aVF = *ecg.lead("aVF");
  double biggest = 0;
  for (std::size_t i = 0; i < ecg.samples(); ++i) {
    EXPECT_NEAR(II[i], I[i] + III[i], 1e-9);
    EXPECT_NEAR(aVR[i] + aVL[i] + aVF[i], 0, 1e-9);
    biggest = std::max(biggest, std::abs(II[i]));
  }
  EXPECT_GT(biggest, 0.1);  // A QRS of a tenth of a millivolt or more: the leads see the heart.
}

TEST(ComputedEcg, AStillHeartIsFlat) {
  // Before the first beat nothing is excited: every lead at 0.
  const Ecg ecg = compute_ecg(heart(), excite(heart(), {}), {1.0}, 0, 0.5, 500);
  for (const auto& lead : ecg.mv)
    for (double v : lead) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace systole::electro
