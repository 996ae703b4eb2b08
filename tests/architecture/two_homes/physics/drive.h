// Half of a planted violation for architecture.one_home_catches_a_copy: the drive in its
// home (physics/), as src/physics/drive.h declares it.
namespace systole::physics {
struct Drive {
  double rate_hz = 0;
};
}  // namespace systole::physics
