#pragma once
// The web page's vendored scripts (third_party/three/: three.js r160, its GLTFLoader,
// OrbitControls and BufferGeometryUtils), embedded at build time by cmake/EmbedViewer.cmake.

#include <string>
#include <vector>

namespace systole::exporter {

struct EmbeddedScript {
  std::string name;  ///< The file's name in third_party/three/.
  std::string text;
};

const std::vector<EmbeddedScript>& embedded_scripts();

/// The text of the embedded script `name`; Error(kInternal) if the build did not embed it.
const std::string& embedded_script(const std::string& name);

}  // namespace systole::exporter
