#pragma once
// The ECG of an organ that has a conduction system (electro/leads.h), on the clip's clock:
// the sinus node fires at each beat of the organ's drives, and the leads are computed from
// the excitation that times the body's contraction, so what the ECG shows is what moves.

#include <optional>
#include <vector>

#include "electro/ecg.h"
#include "world/world.h"

namespace systole::world {

/// Sampling of a computed ECG: fine enough for a QRS complex, the rate EDF readers expect. unit: Hz
inline constexpr double kEcgRateHz = 500;

/// When the sinus node fires, up to `until_s`: the beats of the organ's first driven region
/// (with electrophysiology every driven region beats at its rate). unit: s
std::vector<double> sinus_beats(const sim::Model& model, double until_s);

/// The organ's twelve leads over [0, until_s) at `rate_hz`; nothing when it has no conduction system.
std::optional<electro::Ecg> organ_ecg(const OrganBody& body, double until_s, double rate_hz = kEcgRateHz);

}  // namespace systole::world
