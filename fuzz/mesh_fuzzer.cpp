// Fuzz target: bytes -> a mesh file (the first byte picks the format) -> mesh import
// (assimp, weld) -> placement, inspection and regions -> sim::build_model -> a few steps.
// Bad input must end in a systole::Error; anything else is a bug. Run with scripts/fuzz;
// fuzz/corpus/mesh holds the seeds (first byte, then the file).

#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/error.h"
#include "mesh/organ.h"
#include "sim/from_scene.h"
#include "sim/model.h"
#include "sim/solvers/step.h"
#include "sim/state.h"

namespace {

// The formats docs/own-mesh.md names, plus OFF (a one-line header, easy to mutate).
constexpr std::array<const char*, 6> kExtensions = {".obj", ".stl", ".ply", ".gltf", ".glb", ".off"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace systole;
  if (size == 0) return 0;
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("systole-fuzz-" + std::to_string(::getpid()) + kExtensions[data[0] % kExtensions.size()]);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  scene::Organ organ;
  organ.name = "fuzzed";
  organ.mesh.file = file.string();
  organ.regions.resize(1);
  organ.regions[0].name = "beating";
  organ.regions[0].select.resize(1);  // kAll
  organ.regions[0].drive.waveform = scene::Waveform::kSine;
  organ.regions[0].drive.rate_hz = 1;
  organ.regions[0].drive.amplitude = 0.1;
  try {
    const mesh::OrganGeometry geometry = mesh::build_organ_geometry(organ);
    sim::ModelOptions options;
    options.clip_s = 1;
    const sim::Model model = sim::build_model(sim::organ_params(organ), geometry, options);
    sim::State state = sim::initial_state(model);
    for (int k = 0; k < 4; ++k) sim::step(model, state, options.dt_s);
    (void)sim::diagnose(model, state);
  } catch (const Error&) {
    // A clear error is the right answer to bad input.
  }
  std::filesystem::remove(file);
  return 0;
}
