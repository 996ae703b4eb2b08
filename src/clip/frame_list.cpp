#include "clip/frame_list.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <optional>
#include <string_view>

#include "common/error.h"

namespace systole::clip {
namespace {

[[noreturn]] void bad_syntax(const std::string& list, std::string_view item, const std::string& why) {
  throw Error(ExitCode::kUsage, "bad frame list '" + list + "': '" + std::string(item) + "' " + why +
                                    ". Accepted forms: " + kFrameListForms);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

/// A non-negative decimal integer that fits an int, and nothing else.
std::optional<int> to_frame(std::string_view s) {
  if (s.empty() || s.size() > 10) return std::nullopt;
  long long value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size() || value < 0 || value > INT_MAX) return std::nullopt;
  return static_cast<int>(value);
}

struct Range {
  int first = 0, last = 0, step = 1;
};

/// One item: "N", "A..B", "A..B:S", "A-B" or "A-BxS".
Range parse_item(const std::string& list, std::string_view item) {
  if (item.empty()) bad_syntax(list, item, "is empty (two commas, or a comma at an end)");
  std::string_view span = item, step_text;
  std::size_t dash = item.find("..");
  std::size_t dash_len = 2;
  char step_mark = ':';
  if (dash == std::string_view::npos) {
    dash = item.find('-');
    dash_len = 1;
    step_mark = 'x';
  }
  if (dash != std::string_view::npos) {
    if (const auto mark = item.find(step_mark, dash); mark != std::string_view::npos) {
      span = item.substr(0, mark);
      step_text = item.substr(mark + 1);
      if (step_text.empty()) bad_syntax(list, item, "has no step after its '" + std::string(1, step_mark) + "'");
    }
  }
  Range r;
  if (dash == std::string_view::npos) {
    const auto n = to_frame(item);
    if (!n) bad_syntax(list, item, "is not a frame number");
    r.first = r.last = *n;
    return r;
  }
  const auto first = to_frame(trim(span.substr(0, dash)));
  const auto last = to_frame(trim(span.substr(dash + dash_len)));
  if (!first || !last) bad_syntax(list, item, "is not a range of frame numbers");
  if (*last < *first) bad_syntax(list, item, "ends before it starts");
  r.first = *first;
  r.last = *last;
  if (!step_text.empty()) {
    const auto step = to_frame(trim(step_text));
    if (!step || *step == 0) bad_syntax(list, item, "needs a step of 1 or more");
    r.step = *step;
  }
  return r;
}

}  // namespace

std::vector<int> parse_frame_list(const std::string& text, int frame_count) {
  std::vector<Range> ranges;
  std::string_view rest(text);
  while (true) {
    const auto comma = rest.find(',');
    ranges.push_back(parse_item(text, trim(rest.substr(0, comma))));
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  // Check the end before expanding, so a huge range is an error, not an allocation.
  for (const auto& r : ranges) {
    if (r.last >= frame_count) {
      const int past = r.step == 1 ? r.last : r.first + (r.last - r.first) / r.step * r.step;
      if (past >= frame_count) {
        throw Error(ExitCode::kUsage, "frame " + std::to_string(past) + " is past the clip's end: it has " +
                                          std::to_string(frame_count) + " frames (0.." +
                                          std::to_string(frame_count - 1) + ")");
      }
    }
  }
  std::vector<int> frames;
  for (const auto& r : ranges) {
    for (long long f = r.first; f <= r.last; f += r.step) frames.push_back(static_cast<int>(f));
  }
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  return frames;
}

bool is_contiguous(const std::vector<int>& sorted_frames) {
  return !sorted_frames.empty() &&
         sorted_frames.back() - sorted_frames.front() + 1 == static_cast<int>(sorted_frames.size());
}

}  // namespace systole::clip
