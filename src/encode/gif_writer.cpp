#include "encode/gif_writer.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "common/atomic_output.h"
#include "common/error.h"
#include "encode/av_error.h"
#include "encode/muxer.h"
#include "encode/palette.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
#include <libavutil/opt.h>
}

namespace systole::encode {
namespace {

using detail::av_error_text;

[[noreturn]] void fail(ExitCode code, const std::string& what) { throw Error(code, "GIF encoder: " + what); }

/// A frame's start in centiseconds, the unit of GIF delays: rounding the start (not each
/// delay) keeps the clip's length exact, e.g. 3, 3, 4, 3, 3, 4 cs at 30 fps.
std::int64_t start_cs(std::int64_t frame, double fps) { return std::llround(static_cast<double>(frame) * 100.0 / fps); }

}  // namespace

struct GifWriter::Impl {
  GifSettings settings;
  AtomicOutput output;
  std::FILE* store = nullptr;  ///< Raw RGB frames until finish(); unlinked by tmpfile().
  PaletteBuilder histogram;
  std::int64_t frames = 0;
  int first_index = 0;
  bool finished = false;

  Impl(const std::filesystem::path& target, const GifSettings& s) : settings(s), output(target) {}
  ~Impl() {
    if (store != nullptr) std::fclose(store);
  }
  void encode_all();
};

GifWriter::GifWriter(const std::filesystem::path& target, const GifSettings& s) {
  if (s.width < 1 || s.height < 1 || s.width > 65535 || s.height > 65535) {
    fail(ExitCode::kDataError, "size " + std::to_string(s.width) + "x" + std::to_string(s.height) + " must be in 1..65535");
  }
  if (!std::isfinite(s.fps) || s.fps <= 0 || s.fps > 50) {
    fail(ExitCode::kDataError, "fps " + std::to_string(s.fps) +
                                   " must be in (0, 50]: GIF delays are whole centiseconds and browsers slow "
                                   "faster GIFs down to 10 fps; use 25 or 50");
  }
  impl_ = std::make_unique<Impl>(target, s);
  // Fail on a bad folder now, not after the whole clip.
  if (std::FILE* probe = std::fopen(impl_->output.temp_path().c_str(), "wb")) {
    std::fclose(probe);
  } else {
    throw Error(ExitCode::kCannotCreate, "cannot create '" + impl_->output.target().string() + "': " + std::strerror(errno));
  }
  impl_->store = std::tmpfile();
  if (impl_->store == nullptr) fail(ExitCode::kCannotCreate, std::string("cannot create a temporary file: ") + std::strerror(errno));
}

GifWriter::~GifWriter() = default;

void GifWriter::write(const Image& image, int frame_index) {
  Impl& m = *impl_;
  if (m.finished) fail(ExitCode::kInternal, "write() after finish()");
  if (image.width != m.settings.width || image.height != m.settings.height) {
    fail(ExitCode::kInternal, "frame " + std::to_string(frame_index) + " is " + std::to_string(image.width) + "x" +
                                  std::to_string(image.height) + ", the GIF is " + std::to_string(m.settings.width) +
                                  "x" + std::to_string(m.settings.height));
  }
  if (m.frames == 0) {
    m.first_index = frame_index;
  } else if (frame_index != m.first_index + m.frames) {
    fail(ExitCode::kInternal, "frame " + std::to_string(frame_index) + " arrived; expected frame " +
                                  std::to_string(m.first_index + m.frames));
  }
  m.histogram.add(image);
  if (std::fwrite(image.rgb.data(), 1, image.rgb.size(), m.store) != image.rgb.size()) {
    fail(ExitCode::kIoError, std::string("cannot keep frame ") + std::to_string(frame_index) + " in a temporary file: " + std::strerror(errno));
  }
  ++m.frames;
}

namespace {

/// libavcodec's GIF encoder with its frame and packet, freed together.
struct GifEncoder {
  AVCodecContext* encoder = nullptr;
  AVFrame* frame = nullptr;    ///< Reused for every frame.
  AVPacket* packet = nullptr;  ///< Reused for every packet.

  GifEncoder(const AVCodec* codec, int width, int height);
  ~GifEncoder() {
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&encoder);
  }
  GifEncoder(const GifEncoder&) = delete;
  GifEncoder& operator=(const GifEncoder&) = delete;

  void allocate_frame();
  void fill_frame(const std::vector<std::uint8_t>& indices, const std::vector<PaletteColor>& palette);
  void send(const AVFrame* f, detail::Muxer& muxer, const AVStream* stream);
};

GifEncoder::GifEncoder(const AVCodec* codec, int width, int height) {
  encoder = avcodec_alloc_context3(codec);
  frame = av_frame_alloc();
  packet = av_packet_alloc();
  if (encoder == nullptr || frame == nullptr || packet == nullptr) fail(ExitCode::kInternal, "out of memory");
  encoder->width = width;
  encoder->height = height;
  encoder->pix_fmt = AV_PIX_FMT_PAL8;
  encoder->time_base = AVRational{1, 100};  // GIF delays are centiseconds.
  encoder->flags |= AV_CODEC_FLAG_BITEXACT;
  const int err = avcodec_open2(encoder, codec, nullptr);
  if (err < 0) fail(ExitCode::kInternal, "cannot open the GIF encoder: " + av_error_text(err));
}

void GifEncoder::allocate_frame() {
  frame->format = AV_PIX_FMT_PAL8;
  frame->width = encoder->width;
  frame->height = encoder->height;
  if (av_frame_get_buffer(frame, 0) < 0) fail(ExitCode::kInternal, "out of memory for a frame");
  // Padding beyond the picture is never written; zeroed, no encoder can see what malloc
  // left there (as in encode/video_writer.cpp's allocate_frame).
  for (AVBufferRef* buffer : frame->buf) {
    if (buffer != nullptr) std::memset(buffer->data, 0, buffer->size);
  }
}

/// The frame's palette indices, row by row, and its palette (padded with black to 256).
void GifEncoder::fill_frame(const std::vector<std::uint8_t>& indices, const std::vector<PaletteColor>& palette) {
  if (av_frame_make_writable(frame) < 0) fail(ExitCode::kInternal, "cannot get a writable frame");
  const int width = frame->width;
  for (int y = 0; y < frame->height; ++y) {
    std::memcpy(frame->data[0] + static_cast<std::ptrdiff_t>(y) * frame->linesize[0],
                indices.data() + static_cast<std::size_t>(y) * width, static_cast<std::size_t>(width));
  }
  auto* argb = reinterpret_cast<std::uint32_t*>(frame->data[1]);
  for (std::size_t k = 0; k < 256; ++k) {
    const PaletteColor c = k < palette.size() ? palette[k] : PaletteColor{0, 0, 0};
    argb[k] = 0xFF000000u | static_cast<std::uint32_t>(c[0]) << 16 | static_cast<std::uint32_t>(c[1]) << 8 | c[2];
  }
}

/// Sends one frame (nullptr: flush) and writes every packet the encoder has ready.
void GifEncoder::send(const AVFrame* f, detail::Muxer& muxer, const AVStream* stream) {
  int err = avcodec_send_frame(encoder, f);
  if (err < 0) fail(ExitCode::kInternal, "the GIF encoder refused a frame: " + av_error_text(err));
  while ((err = avcodec_receive_packet(encoder, packet)) == 0) muxer.write(packet, encoder->time_base, stream);
  if (err != AVERROR(EAGAIN) && err != AVERROR_EOF) fail(ExitCode::kInternal, "the GIF encoder failed: " + av_error_text(err));
}

}  // namespace

void GifWriter::Impl::encode_all() {
  detail::quiet_libav_logging();
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_GIF);
  if (codec == nullptr) fail(ExitCode::kInternal, "this FFmpeg build has no GIF encoder");
  detail::Muxer muxer(output, "gif", "GIF");
  GifEncoder gif(codec, settings.width, settings.height);  // Freed before the muxer.
  AVStream* stream = avformat_new_stream(muxer.context(), nullptr);
  if (stream == nullptr) fail(ExitCode::kInternal, "cannot add a video stream");
  stream->time_base = gif.encoder->time_base;
  avcodec_parameters_from_context(stream->codecpar, gif.encoder);
  muxer.write_header({{"loop", "0"}});  // Loop forever: slides.
  gif.allocate_frame();

  PaletteMapper mapper(histogram.build(256));
  Image image(settings.width, settings.height);
  std::vector<std::uint8_t> indices;
  std::rewind(store);
  for (std::int64_t i = 0; i < frames; ++i) {
    if (std::fread(image.rgb.data(), 1, image.rgb.size(), store) != image.rgb.size()) {
      fail(ExitCode::kIoError, "cannot read back a kept frame");
    }
    mapper.map(image, indices);
    gif.fill_frame(indices, mapper.palette());
    gif.frame->pts = start_cs(i, settings.fps);
    gif.send(gif.frame, muxer, stream);
  }
  gif.send(nullptr, muxer, stream);
  muxer.finish();
}

void GifWriter::finish() {
  Impl& m = *impl_;
  if (m.finished) fail(ExitCode::kInternal, "finish() called twice");
  if (m.frames == 0) fail(ExitCode::kInternal, "no frame was written to '" + m.output.target().string() + "'");
  m.encode_all();
  m.output.commit();
  m.finished = true;
}

}  // namespace systole::encode
