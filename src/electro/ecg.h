#pragma once
// The body-surface ECG computed from the heart's excitation (electro/leads.h): the twelve
// standard leads, evenly sampled at a rate of their own (not the solver's step).

#include <string>
#include <vector>

namespace systole::electro {

/// The twelve standard leads in the usual order.
inline const std::vector<std::string>& standard_leads() {
  static const std::vector<std::string> names = {"I", "II", "III", "aVR", "aVL", "aVF",
                                                 "V1", "V2", "V3", "V4", "V5", "V6"};
  return names;
}

/// Leads sampled evenly: mv[lead][i] at t = start_s + i / rate_hz.
struct Ecg {
  double rate_hz = 500;             ///< unit: Hz
  double start_s = 0;               ///< Time of sample 0 on the clip's clock. unit: s
  std::vector<std::string> leads;   ///< Names, standard_leads() order.
  std::vector<std::vector<double>> mv;  ///< Per lead, its samples. unit: mV

  std::size_t samples() const { return mv.empty() ? 0 : mv.front().size(); }
  /// The samples of the lead named `name`, or null.
  const std::vector<double>* lead(const std::string& name) const {
    for (std::size_t i = 0; i < leads.size(); ++i) {
      if (leads[i] == name) return &mv[i];
    }
    return nullptr;
  }
};

}  // namespace systole::electro
