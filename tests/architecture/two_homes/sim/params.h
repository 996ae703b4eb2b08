// The other half of the planted violation for architecture.one_home_catches_a_copy: the
// simulator keeps its own copy of the drive instead of `using physics::Drive;`.
namespace systole::sim {
struct Drive {
  double rate_hz = 0;
};
}  // namespace systole::sim
