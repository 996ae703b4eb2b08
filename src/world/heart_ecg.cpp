#include "world/heart_ecg.h"

#include "electro/leads.h"
#include "sim/drive.h"

namespace systole::world {

std::vector<double> sinus_beats(const sim::Model& model, double until_s) {
  for (std::size_t r = 0; r < model.regions.size(); ++r) {
    const sim::Drive& drive = model.regions[r].drive;
    if (drive.waveform == sim::Waveform::kNone) continue;
    const std::vector<double> regular;
    return sim::beat_start_times(drive, r < model.beat_boundaries.size() ? model.beat_boundaries[r] : regular,
                                 model.ramp_s, until_s);
  }
  return {};
}

std::optional<electro::Ecg> organ_ecg(const OrganBody& body, double until_s, double rate_hz) {
  if (!body.model.excitation) return std::nullopt;
  // A beat's repolarisation outlasts its cycle's start: the one before 0 is not drawn, and
  // the first beat starts at rest, as the body does.
  return electro::compute_ecg(body.geometry.mesh, *body.model.excitation, sinus_beats(body.model, until_s + 1.0), 0.0,
                              until_s, rate_hz);
}

}  // namespace systole::world
