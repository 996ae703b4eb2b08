#pragma once
// Captions as a WebVTT file (W3C, "WebVTT: The Web Video Text Tracks Format"), beside the
// video, for players and pages that load subtitles from a file.

#include <filesystem>
#include <string>
#include <vector>

#include "encode/video_writer.h"

namespace systole::encode {

/// "00:01:02.345": a WebVTT timestamp, rounded to the millisecond. unit: s
std::string webvtt_time(double t_s);

/// The text of a WebVTT file with `cues` (numbered from 1; "&", "<" and ">" escaped).
std::string webvtt_text(const std::vector<TextCue>& cues);

/// Writes it to `target`, whole or not at all (common/atomic_output.h).
void write_webvtt(const std::filesystem::path& target, const std::vector<TextCue>& cues);

}  // namespace systole::encode
