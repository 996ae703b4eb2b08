#include "encode/webvtt.h"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "common/atomic_output.h"
#include "common/error.h"

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
  AtomicOutput output(target);
  {
    std::ofstream file(output.temp_path(), std::ios::binary);
    if (!file) throw Error(ExitCode::kCannotCreate, "cannot create '" + output.temp_path().string() + "'");
    const std::string text = webvtt_text(cues);
    file.write(text.data(), static_cast<std::streamsize>(text.size()));
    file.close();
    if (!file) throw Error(ExitCode::kIoError, "cannot write '" + output.temp_path().string() + "'");
  }
  output.commit();
}

}  // namespace systole::encode
