#pragma once
// One output file written through libavformat (internal to encode/; not part of the API):
// the muxer's context, the file, its header and trailer, and the tear-down, the same for
// every writer. It writes an AtomicOutput's temporary; the caller commits.

#include <string>
#include <utility>
#include <vector>

#include "common/atomic_output.h"

extern "C" {
#include <libavformat/avformat.h>
}

namespace systole::encode::detail {

class Muxer {
 public:
  /// The context of libavformat's muxer `name` ("mp4", "gif", ...) for `output`'s
  /// temporary, bit-exact (no random IDs, dates or library versions: the same packets give
  /// the same bytes). The format is forced: a temporary's name is nothing to guess it from.
  /// Errors throw Error with "<label> encoder: ...", naming the target the user asked for (not
  /// the hidden temporary). `output` must outlive the Muxer.
  Muxer(const AtomicOutput& output, const char* name, std::string label);
  /// Closes the file if still open and frees the context (and its streams).
  ~Muxer();
  Muxer(const Muxer&) = delete;
  Muxer& operator=(const Muxer&) = delete;

  /// The context, to add streams and chapters to. Owned by the Muxer.
  AVFormatContext* context() const { return format_; }

  /// Opens the temporary and writes the header with the muxer's `options` (key, value).
  /// Throws Error(kCannotCreate) when the file cannot be created, Error(kIoError) when the
  /// header cannot be written.
  void write_header(const std::vector<std::pair<const char*, const char*>>& options);

  /// Writes `packet` (its time stamps in `time_base`) to `stream`, through the muxer's
  /// interleaving queue, and unreferences it. Throws Error(kIoError) on failure.
  void write(AVPacket* packet, AVRational time_base, const AVStream* stream);

  /// Writes the trailer and closes the file. Throws Error(kIoError) on failure.
  void finish();

 private:
  const AtomicOutput& output_;
  std::string label_;
  AVFormatContext* format_ = nullptr;
  bool open_ = false;  ///< The header is written and the trailer is not.
};

}  // namespace systole::encode::detail
