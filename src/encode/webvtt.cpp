#include "encode/webvtt.h"

#include <cmath>
#include <cstdio>

#include "common/atomic_output.h"

namespace systole::encode {

std::string webvtt_time(double t_s) {
  const long long ms = std::llround(t_s * 1000.0);
  char text[32];
  std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld.%03lld", ms / 3600000, ms / 60000 % 60, ms / 1000 % 60, ms % 1000);
  return text;
}

std::string webvtt_text(const std::vector<TextCue>& cues) {
  std::string out = "WEBVTT\n";
  for (std::size_t i = 0; i < cues.size(); ++i) {
    out += "\n" + std::to_string(i + 1) + "\n" + webvtt_time(cues[i].from_s) + " --> " + webvtt_time(cues[i].to_s) + "\n";
    for (char c : cues[i].text) {
      if (c == '&') out += "&amp;";
      else if (c == '<') out += "&lt;";
      else if (c == '>') out += "&gt;";
      else out += c;
    }
    out += "\n";
  }
  return out;
}

void write_webvtt(const std::filesystem::path& target, const std::vector<TextCue>& cues) {
  write_file_atomically(target, webvtt_text(cues));
}

}  // namespace systole::encode
