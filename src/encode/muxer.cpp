#include "encode/muxer.h"

#include "common/error.h"
#include "encode/av_error.h"

namespace systole::encode::detail {

Muxer::Muxer(const AtomicOutput& output, const char* name, std::string label) : output_(output), label_(std::move(label)) {
  const int err = avformat_alloc_output_context2(&format_, nullptr, name, output_.temp_path().c_str());
  if (err < 0 || format_ == nullptr) {
    throw Error(ExitCode::kInternal, label_ + " encoder: cannot set up the muxer: " + av_error_text(err));
  }
  format_->flags |= AVFMT_FLAG_BITEXACT;
}

Muxer::~Muxer() {
  if (format_ == nullptr) return;
  // A muxer that failed part-way (a full disk) still holds what it keeps between packets:
  // FFmpeg 5.1's GIF muxer frees its held packet only in the trailer. Written into the
  // temporary that is about to be removed; its error is the one already reported.
  if (open_) av_write_trailer(format_);
  if (format_->pb != nullptr) avio_closep(&format_->pb);
  avformat_free_context(format_);
}

void Muxer::write_header(const std::vector<std::pair<const char*, const char*>>& options) {
  int err = avio_open(&format_->pb, output_.temp_path().c_str(), AVIO_FLAG_WRITE);
  if (err < 0) {
    throw Error(ExitCode::kCannotCreate, "cannot create '" + output_.target().string() + "': " + av_error_text(err));
  }
  AVDictionary* dictionary = nullptr;
  for (const auto& [key, value] : options) av_dict_set(&dictionary, key, value, 0);
  err = avformat_write_header(format_, &dictionary);
  av_dict_free(&dictionary);
  open_ = err >= 0;
  if (err < 0) {
    throw Error(ExitCode::kIoError, label_ + " encoder: cannot write the header of '" + output_.target().string() +
                                        "': " + av_error_text(err));
  }
}

void Muxer::write(AVPacket* packet, AVRational time_base, const AVStream* stream) {
  av_packet_rescale_ts(packet, time_base, stream->time_base);
  packet->stream_index = stream->index;
  const int err = av_interleaved_write_frame(format_, packet);  // Takes the packet's reference.
  av_packet_unref(packet);
  if (err < 0) {
    throw Error(ExitCode::kIoError,
                label_ + " encoder: cannot write to '" + output_.target().string() + "': " + av_error_text(err));
  }
}

void Muxer::finish() {
  open_ = false;
  int err = av_write_trailer(format_);  // With MP4's +faststart this also moves moov to the front.
  if (err < 0) {
    throw Error(ExitCode::kIoError, label_ + " encoder: cannot finish '" + output_.target().string() + "': " + av_error_text(err));
  }
  err = avio_closep(&format_->pb);
  if (err < 0) {
    throw Error(ExitCode::kIoError, label_ + " encoder: cannot close '" + output_.target().string() + "': " + av_error_text(err));
  }
}

}  // namespace systole::encode::detail
