#include "study/renderer_key.h"

#include <algorithm>
#include <cctype>

namespace systole::study {
namespace {

/// Lower case; runs of anything but [a-z0-9.] become one dash; no dash at either end.
std::string slug(const std::string& text) {
  std::string out;
  for (const char raw : text) {
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(raw)));
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '.') {
      out += c;
    } else if (!out.empty() && out.back() != '-') {
      out += '-';
    }
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

}  // namespace

std::string renderer_key(const render::GlInfo& gl) {
  const auto open = gl.renderer.find('(');
  const std::string driver = gl.renderer.substr(0, open);
  std::string details;
  if (open != std::string::npos) {
    // "LLVM 15.0.6, 256 bits": keep every item but the vector width.
    const std::string inside = gl.renderer.substr(open + 1, gl.renderer.find(')', open) - open - 1);
    for (std::size_t at = 0; at <= inside.size();) {
      const auto comma = std::min(inside.find(',', at), inside.size());
      const std::string item = inside.substr(at, comma - at);
      if (item.size() < 5 || item.compare(item.size() - 5, 5, " bits") != 0) details += " " + item;
      at = comma + 1;
    }
  }
  const auto mesa = gl.version.find("Mesa ");
  const std::string version = mesa == std::string::npos ? gl.version : "mesa " + gl.version.substr(mesa + 5);
  return slug(driver + " " + version + " " + details);
}

}  // namespace systole::study
