#pragma once
// The clip's captions and chapters as the video's text tracks: a subtitle track in the
// container, a .vtt file beside the video, and chapter marks (each title card, then the
// scene's `chapters`). Times are video time, like the burned-in captions.

#include <filesystem>
#include <vector>

#include "encode/video_writer.h"
#include "scene/scene.h"

namespace systole::clip {

/// Frames of each title card: round(duration * fps), at least one (overlay/cards.h).
std::vector<int> card_frame_counts(const scene::Scene& scene);

/// The captions as cues of a video of clip frames [first_frame, last_frame] that starts
/// with `cards_s` of title cards: shifted by the cards and by the range's start, cut to the
/// video, dropped when outside it. unit: s
std::vector<encode::TextCue> caption_cues(const scene::Scene& scene, int first_frame, int last_frame, double cards_s);

/// Chapter marks of that video: one per title card (its first line), then the scene's
/// chapters; each ends where the next starts, the last at the video's end.
std::vector<encode::ChapterMark> chapter_marks(const scene::Scene& scene, int first_frame, int last_frame, double cards_s);

/// Where the captions' WebVTT file goes: the video's path with the extension .vtt.
std::filesystem::path webvtt_path(const std::filesystem::path& video);

}  // namespace systole::clip
