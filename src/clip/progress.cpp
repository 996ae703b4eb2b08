#include "clip/progress.h"

#include <unistd.h>

#include <cstdio>

#include "common/json.h"

namespace systole::clip {

Progress::Progress(std::string label, int total, ProgressStyle style)
    : label_(std::move(label)), total_(total), style_(style), start_(std::chrono::steady_clock::now()) {}

bool Progress::stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

void Progress::update(int done) {
  if (style_ == ProgressStyle::kNone) return;
  const auto now = std::chrono::steady_clock::now();
  const auto interval = std::chrono::milliseconds(style_ == ProgressStyle::kJson ? 500 : 100);
  if (done < total_ && now - last_draw_ < interval) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? done / elapsed : 0;
  const double eta = rate > 0 ? (total_ - done) / rate : 0;
  if (style_ == ProgressStyle::kJson) {
    // One write per line: lines from parallel jobs sharing the pipe never interleave.
    std::printf("{\"job\": %s, \"frame\": %d, \"frames\": %d, \"fps\": %.2f, \"eta_s\": %.1f}\n",
                json_quote(label_).c_str(), done, total_, rate, eta);
    std::fflush(stdout);
    return;
  }
  std::fprintf(stderr, "\r%s: frame %d/%d  %3.0f%%  %5.1f fps  ETA %d:%02d   ", label_.c_str(), done, total_,
               total_ > 0 ? 100.0 * done / total_ : 100.0, rate, int(eta) / 60, int(eta) % 60);
  std::fflush(stderr);
}

void Progress::finish() {
  if (style_ != ProgressStyle::kTerminal) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
}

}  // namespace systole::clip
