#include "clip/text_tracks.h"

#include <algorithm>
#include <cmath>

namespace systole::clip {

std::vector<int> card_frame_counts(const scene::Scene& scene) {
  std::vector<int> frames;
  for (const scene::Card& card : scene.cards)
    frames.push_back(std::max(1, static_cast<int>(std::lround(card.duration_s * scene.output.fps))));
  return frames;
}

std::vector<encode::TextCue> caption_cues(const scene::Scene& scene, int first_frame, int last_frame, double cards_s) {
  const double fps = scene.output.fps;
  const double shift = cards_s - first_frame / fps;
  const double end = cards_s + (last_frame - first_frame + 1) / fps;
  std::vector<encode::TextCue> cues;
  for (const scene::Caption& c : scene.captions) {
    const double from = std::max(cards_s, c.from_s + shift), to = std::min(end, c.to_s + shift);
    if (to > from) cues.push_back({from, to, c.text});
  }
  std::stable_sort(cues.begin(), cues.end(), [](const encode::TextCue& a, const encode::TextCue& b) { return a.from_s < b.from_s; });
  return cues;
}

std::vector<encode::ChapterMark> chapter_marks(const scene::Scene& scene, int first_frame, int last_frame, double cards_s) {
  const double fps = scene.output.fps;
  const double end = cards_s + (last_frame - first_frame + 1) / fps;
  std::vector<encode::ChapterMark> marks;
  if (cards_s > 0) {
    const std::vector<int> frames = card_frame_counts(scene);
    int first = 0;
    for (std::size_t i = 0; i < scene.cards.size(); ++i) {
      const std::string& text = scene.cards[i].text;
      marks.push_back({first / fps, 0, text.substr(0, text.find('\n'))});
      first += frames[i];
    }
  }
  for (const scene::Chapter& c : scene.chapters) {
    const double at = cards_s + c.at_s - first_frame / fps;
    if (at < cards_s || at >= end) continue;
    // A chapter at the clip's start replaces the last card's run into the clip; it is not a second mark there.
    marks.push_back({at, 0, c.title});
  }
  for (std::size_t i = 0; i < marks.size(); ++i) marks[i].end_s = i + 1 < marks.size() ? marks[i + 1].start_s : end;
  return marks;
}

std::filesystem::path webvtt_path(const std::filesystem::path& video) {
  std::filesystem::path p = video;
  p.replace_extension(".vtt");
  return p;
}

}  // namespace systole::clip
