// ctest-labels: slow-under-sanitizers
// The shipped bundle branch blocks, measured as `validate --physiology` measures them: each
// scene's computed ECG meets the AHA/ACCF/HRS criteria for its block (Surawicz et al. 2009,
// "AHA/ACCF/HRS recommendations for the standardization and interpretation of the
// electrocardiogram, part III: intraventricular conduction disturbances", Circulation
// 119:e235), and the left block's ventricle contracts out of step and ejects less. The
// normal heart with the same conduction system (heart, heart-conduction) meets none of them.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "scene/load.h"
#include "study/physiology.h"
#include "support/run.h"

namespace systole::study {
namespace {

const PhysiologyReport& shipped(const std::string& name) {
  static std::map<std::string, PhysiologyReport> reports;
  auto it = reports.find(name);
  if (it == reports.end()) it = reports.emplace(name, measure_physiology(scene::load(test::source("scenes/" + name + ".yaml")))).first;
  return it->second;
}

const electro::LeadWaves& lead(const PhysiologyReport& r, const char* name) {
  return r.ecg.leads[static_cast<std::size_t>(electro::lead_index(name))];
}

/// A broad R (lasting most of the QRS) that is notched (two peaks) or slurred (its peak 50 ms
/// or more into the QRS), and no q before it.
void expect_broad_r_without_q(const PhysiologyReport& r, const char* name) {
  const electro::LeadWaves& w = lead(r, name);
  SCOPED_TRACE(name);
  EXPECT_GT(w.r, w.s) << "a dominant R";
  EXPECT_GE(w.r_duration_s, 0.6 * r.ecg.qrs_s) << "broad";
  EXPECT_TRUE(w.r_peaks >= 2 || w.r_peak_time_s >= 0.050) << "notched or slurred: " << w.r_peaks << " peaks, R peak at "
                                                           << 1000 * w.r_peak_time_s << " ms";
  EXPECT_EQ(w.q, 0.0) << "no septal q";
}

TEST(BundleBranchBlock, TheShippedLeftBlockMeetsTheAhaCriteria) {
  const PhysiologyReport& r = shipped("heart-lbbb");
  ASSERT_TRUE(r.has_ecg);
  EXPECT_GE(r.ecg.qrs_s, 0.120);
  for (const char* name : {"I", "aVL", "V5", "V6"}) expect_broad_r_without_q(r, name);
  // V1: QS or rS - an S with at most a small r before it, and no R after it.
  const electro::LeadWaves& v1 = lead(r, "V1");
  EXPECT_LT(v1.r, 0.25 * v1.s);
  EXPECT_EQ(v1.r_prime, 0.0);
  EXPECT_EQ(v1.q, 0.0) << "QS or rS, not qR";
}

TEST(BundleBranchBlock, TheShippedRightBlockMeetsTheAhaCriteria) {
  const PhysiologyReport& r = shipped("heart-rbbb");
  ASSERT_TRUE(r.has_ecg);
  EXPECT_GE(r.ecg.qrs_s, 0.120);
  // V1: an R' after an S (rsR'), the R' taller than the first r.
  const electro::LeadWaves& v1 = lead(r, "V1");
  EXPECT_GE(v1.r_peaks, 2);
  EXPECT_GT(v1.r_prime, 0.0);
  EXPECT_GT(v1.s, 0.0);
  // A wide S in I and V6: longer than 40 ms, or than the R.
  for (const char* name : {"I", "V6"}) {
    const electro::LeadWaves& w = lead(r, name);
    EXPECT_TRUE(w.s_duration_s > 0.040 || w.s_duration_s > w.r_duration_s)
        << name << ": S " << 1000 * w.s_duration_s << " ms, R " << 1000 * w.r_duration_s << " ms";
  }
}

// The shipped normal heart and heart-conduction (the same organ with the ECG shown): every
// figure normal (PR, QRS, QTc, axis, transition among them), the polarities of a normal ECG,
// and neither block's criteria.
TEST(BundleBranchBlock, TheNormalHeartMeetsNeither) {
  for (const char* name : {"heart", "heart-conduction"}) {
    SCOPED_TRACE(name);
    const PhysiologyReport& r = shipped(name);
    ASSERT_TRUE(r.has_ecg);
    EXPECT_TRUE(r.outside_normal().empty()) << physiology_text(r);
    for (const char* lead_name : {"I", "II", "V5", "V6"}) EXPECT_GT(lead(r, lead_name).r, lead(r, lead_name).s) << lead_name;
    EXPECT_GT(lead(r, "aVR").s, lead(r, "aVR").r);
    for (const char* lead_name : {"I", "II", "V4", "V5", "V6"}) EXPECT_GT(lead(r, lead_name).t, 0) << lead_name;
    EXPECT_LT(r.ecg.qrs_s, 0.110);
    EXPECT_GT(lead(r, "V6").q, 0.0) << "the septum, excited from the left, gives V6 its q";
    EXPECT_EQ(lead(r, "V1").r_prime, 0.0) << "no R' in V1";
    EXPECT_LT(std::abs(r.septal_lateral_delay_ms), kDyssynchronyDelayMs);
  }
}

// LBBB's mechanics: the septum, excited some 90 ms before the lateral wall, peaks earlier
// than the normal heart's does against its lateral wall, and the out-of-step contraction
// ejects less. (The issue asks for a 60-ms septal-to-lateral delay; the model reaches 56 ms
// at the scene's step and 43 ms converged: docs/electrophysiology.md.)
TEST(BundleBranchBlock, TheLeftBlocksVentricleIsOutOfStepAndEjectsLess) {
  const PhysiologyReport& normal = shipped("heart-conduction");
  const PhysiologyReport& lbbb = shipped("heart-lbbb");
  EXPECT_GE(lbbb.septal_lateral_delay_ms, normal.septal_lateral_delay_ms + 20) << physiology_text(lbbb);
  EXPECT_LE(lbbb.ejection_fraction_pct, normal.ejection_fraction_pct - 3)
      << "normal " << normal.ejection_fraction_pct << " %, LBBB " << lbbb.ejection_fraction_pct << " %";
  // The right block leaves the left ventricle in step.
  EXPECT_LT(std::abs(shipped("heart-rbbb").septal_lateral_delay_ms - normal.septal_lateral_delay_ms), 10.0);
}

}  // namespace
}  // namespace systole::study
