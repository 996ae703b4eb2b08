#pragma once
// A region's rhythm (what the simulator's builder reads): waveforms, drives and path keys.
// The types are the simulator's own (physics/drive.h): the scene holds no field the
// simulator does not run on, so it has no copy of them to translate (sim/from_scene.h).

#include "physics/drive.h"

namespace systole::scene {

using physics::Drive;
using physics::Harmonic;
using physics::PathKey;
using physics::Waveform;

}  // namespace systole::scene
