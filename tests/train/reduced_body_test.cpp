// Training ties each particle to its own target vertex, so an organ whose body is reduced (a
// lattice of other particles) is refused with what to change, not read out of bounds (it
// crashed `systole tune` with SIGSEGV).

#include <gtest/gtest.h>

#include "common/error.h"
#include "scene/load.h"
#include "train/playback.h"
#include "train/train_test_util.h"

namespace systole::train {
namespace {

using namespace testing;

TEST(ReducedBody, ATargetOnALatticeBodyIsRefusedWithTheKeyToChange) {
  const auto dir = scratch("reduced_body");
  const mesh::TriangleMesh ball = icosphere(2);
  write_obj(dir / "ball.obj", ball.positions, ball.triangles);
  const std::string drive = "{waveform: sine, rate: 1 Hz, amplitude: 0.1}";
  const std::string target = "    target:\n      rate: 1 Hz\n      curves:\n        - {region: top, volume: [1, 0.9, 0.8, 0.9]}\n";
  std::string yaml = ball_scene(drive, drive, target);
  write_text(dir / "full.yaml", yaml);
  EXPECT_NO_THROW(make_problem(scene::load(dir / "full.yaml"), 0));
  yaml.replace(yaml.find("drag: 4 1/s}"), 12, "drag: 4 1/s, lattice: 4}");
  write_text(dir / "lattice.yaml", yaml);
  try {
    make_problem(scene::load(dir / "lattice.yaml"), 0);
    FAIL() << "a lattice body was trained against its surface";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("lattice.yaml:3:5: organ 'ball': its target moves the 162 vertices of its surface, "
                                         "and its body has "),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("give this organ body.lattice: 0 to tune it"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace systole::train
