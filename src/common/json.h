#pragma once
// Writing JSON by hand for the few flat objects Systole prints (progress lines, job
// manifests): quoting is the only part that needs care.

#include <cstdio>
#include <string>
#include <string_view>

namespace systole {

/// `text` as a JSON string literal, quotes included (RFC 8259 escapes).
inline std::string json_quote(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char esc[8];
          std::snprintf(esc, sizeof esc, "\\u%04x", c);
          out += esc;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

}  // namespace systole
