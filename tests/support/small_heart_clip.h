#pragma once
// A small, cheap beating heart scene for tests that render whole clips: 72 bpm, a coarse
// lattice, XPBD at 1/120 s, 160x120 frames. `output` is spliced into the output map
// (e.g. "duration: 1 s, file: a.mp4"), `extra` appended as more top-level keys.

#include <string>

namespace systole::test {

inline std::string small_heart_scene(const std::string& output, const std::string& extra = "") {
  return "organs:\n  - name: heart\n    mesh: {procedural: heart, detail: 3}\n"
         "    body: {mass: 300 g, stiffness: 400 N/m, damping: 10 ms, volume_stiffness: 3 kPa, drag: 2 1/s, lattice: 8}\n"
         "    regions:\n"
         "      - {name: left_atrium, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.10, systolic_fraction: 0.15}}\n"
         "      - {name: left_ventricle, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.14, delay: 160 ms}}\n"
         "      - {name: aorta, pinned: true}\n"
         "solver: {method: xpbd, dt: 1/120 s, substeps: 2}\n"
         "camera: {position: [0, 0.01, 0.34], target: [0, 0, 0], fov: 40 deg}\n"
         "output: {width: 160, height: 120, fps: 30, " + output + "}\n" + extra;
}

}  // namespace systole::test
