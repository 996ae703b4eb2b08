#include "study/info.h"

#include <assimp/version.h>
#include <Eigen/Core>
#include <sstream>

#include "encode/versions.h"
#include "render/renderer.h"
#include "study/renderer_key.h"

namespace systole::study {

std::string system_info() {
  std::ostringstream s;
  s << "systole " << SYSTOLE_VERSION << "\n";
  s << "eigen " << EIGEN_WORLD_VERSION << "." << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION << "\n";
  s << "assimp " << aiGetVersionMajor() << "." << aiGetVersionMinor() << "." << aiGetVersionPatch() << "\n";
  for (const auto& v : encode::library_versions()) s << v << "\n";
  s << "h264 encoders:";
  for (const auto& e : encode::h264_encoders()) s << " " << e;
  s << "\n";
  s << "output formats:";
  for (const auto& f : encode::output_formats()) s << " " << f;
  s << "\n";
  render::Renderer probe(16, 16, 0);
  const auto gl = probe.info();
  s << "gl vendor " << gl.vendor << "\n";
  s << "gl renderer " << gl.renderer << "\n";
  s << "gl version " << gl.version << "\n";
  s << "glsl version " << gl.glsl_version << "\n";
  s << "golden key " << renderer_key(gl) << "\n";
  return s.str();
}

}  // namespace systole::study
