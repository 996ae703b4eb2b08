#pragma once
// What every scene struct shares: where a value was written, and colours as users pick them.

#include <Eigen/Core>
#include <string>

namespace systole::scene {

/// Where a value was written: for error messages that point back into the YAML.
struct Origin {
  std::string file;  ///< Scene path, or "-D key=value" for a command-line override.
  int line = 0;      ///< 1-based; 0 when unknown.
  int column = 0;    ///< 1-based; 0 when unknown.
};

/// An sRGB colour as users pick them ("#b8322a" or [0.72, 0.2, 0.16]), each channel in
/// [0, 1]; render/ converts to linear light for shading and back for output.
using Color = Eigen::Vector3d;

}  // namespace systole::scene
