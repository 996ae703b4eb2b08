#pragma once
// Text placed in an XML or HTML element's content (an SVG chart's labels, the export page's
// title): the three characters that would start markup or an entity are escaped.

#include <string>

namespace systole {

inline std::string xml_text(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

}  // namespace systole
