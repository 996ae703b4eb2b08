#include "encode/video_writer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

#include "common/atomic_output.h"
#include "common/error.h"
#include "encode/av_error.h"
#include "encode/gif_writer.h"
#include "encode/muxer.h"
#include "encode/text_streams.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/channel_layout.h>
#include <libavutil/cpu.h>
#include <libavutil/dict.h>
#include <libavutil/frame.h>
#include <libavutil/opt.h>
#include <libavutil/rational.h>
#include <libswscale/swscale.h>
}

namespace systole::encode {
namespace {

using detail::av_error_text;

constexpr std::array<std::string_view, 10> kX264Presets = {
    "ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow", "placebo"};

/// What differs between the formats VideoWriter writes.
struct Codec {
  const char* encoder;   ///< libavcodec encoder name.
  const char* muxer;     ///< libavformat muxer name.
  const char* label;     ///< For messages: "MP4", ...
  AVPixelFormat pix_fmt;
  bool yuv;              ///< BT.709 limited-range YUV; otherwise full-range RGB planes.
  const char* audio_encoder;     ///< The soundtrack's libavcodec encoder.
  std::int64_t audio_bit_rate;   ///< unit: bit/s; 0 for a lossless codec.
  const char* subtitle_encoder;  ///< The text track's encoder (it takes ASS dialogue lines).
};

const Codec& codec_of(VideoFormat f) {
  // Audio: AAC at 96 kbit/s mono is transparent for these low-pitched sounds; Opus at 64
  // kbit/s likewise; FLAC keeps the lossless archive lossless. Text: the one subtitle codec
  // each container's players read (mov_text is MP4's timed text, 3GPP TS 26.245).
  static const Codec mp4{"libx264", "mp4", "MP4", AV_PIX_FMT_YUV420P, true, "aac", 96000, "mov_text"};
  static const Codec mkv{"ffv1", "matroska", "MKV", AV_PIX_FMT_BGR0, false, "flac", 0, "srt"};
  static const Codec webm{"libvpx-vp9", "webm", "WebM", AV_PIX_FMT_YUV420P, true, "libopus", 64000, "webvtt"};
  switch (f) {
    case VideoFormat::kMkv: return mkv;
    case VideoFormat::kWebm: return webm;
    default: return mp4;
  }
}

[[noreturn]] void fail(ExitCode code, const std::string& what, VideoFormat f) {
  throw Error(code, std::string(codec_of(f).label) + " encoder: " + what);
}

void validate(const VideoSettings& s) {
  const auto fail = [&](ExitCode code, const std::string& what) { ::systole::encode::fail(code, what, s.format); };
  if (s.format == VideoFormat::kGif) fail(ExitCode::kInternal, "GIF is GifWriter's (open_video)");
  if (s.width <= 0 || s.height <= 0) {
    fail(ExitCode::kDataError, "video size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                   " must be positive");
  }
  if (s.width % 2 != 0 || s.height % 2 != 0) {
    const int w = s.width, h = s.height;
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    const std::string down = std::to_string(w - w % 2) + "x" + std::to_string(h - h % 2);
    const std::string up = std::to_string(w + w % 2) + "x" + std::to_string(h + h % 2);
    throw Error(ExitCode::kDataError,
                "H.264 in yuv420p needs even sizes: " + size + " is odd; use " + down + " or " + up);
  }
  if (s.width > 16384 || s.height > 16384) {
    fail(ExitCode::kDataError, "video size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                   " exceeds 16384 px");
  }
  if (!std::isfinite(s.fps) || s.fps <= 0 || s.fps > 1000) {
    fail(ExitCode::kDataError, "fps " + std::to_string(s.fps) + " must be in (0, 1000] frames/s");
  }
  if (s.crf < 0 || s.crf > 51) {
    fail(ExitCode::kDataError, "crf " + std::to_string(s.crf) + " must be in 0..51 (lower is better quality)");
  }
  bool known = false;
  std::string list;
  for (auto p : kX264Presets) {
    known = known || p == s.preset;
    list += (list.empty() ? "" : ", ") + std::string(p);
  }
  if (!known) fail(ExitCode::kDataError, "unknown x264 preset '" + s.preset + "'; use one of " + list);
  if (s.vp9_crf < 0 || s.vp9_crf > 63) fail(ExitCode::kDataError, "VP9 crf " + std::to_string(s.vp9_crf) + " must be in 0..63");
  if (s.vp9_speed < 0 || s.vp9_speed > 5) fail(ExitCode::kDataError, "VP9 speed " + std::to_string(s.vp9_speed) + " must be in 0..5");
  if (s.threads < 0 || s.threads > 64) {
    fail(ExitCode::kDataError, "threads " + std::to_string(s.threads) + " must be in 0..64 (0 = automatic)");
  }
}

/// The instruction sets x264 may use, as its `asm` option names them: what x264 itself
/// detects, less AVX-512 (VideoWriter::Impl::encoder_options says why). Empty when the
/// CPU has no AVX-512: x264's own detection then stands as it is.
std::string x264_cpu_without_avx512() {
  const int cpu = av_get_cpu_flags();  // AVX512 here means what x264 needs: F, CD, BW, DQ, VL and the OS's ZMM state.
  if ((cpu & AV_CPU_FLAG_AVX512) == 0) return {};
  bool lzcnt = false;  // x264 takes LZCNT from the extended leaf (ABM); libavutil has no flag for it.
#if defined(__x86_64__) || defined(__i386__)
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  lzcnt = __get_cpuid(0x80000001, &eax, &ebx, &ecx, &edx) != 0 && (ecx & bit_ABM) != 0;
#endif
  const std::pair<int, const char*> features[] = {
      {AV_CPU_FLAG_MMXEXT, "MMX2"}, {AV_CPU_FLAG_SSE, "SSE"},     {AV_CPU_FLAG_SSE2, "SSE2"},
      {AV_CPU_FLAG_SSE3, "SSE3"},   {AV_CPU_FLAG_SSSE3, "SSSE3"}, {AV_CPU_FLAG_SSE4, "SSE4.1"},
      {AV_CPU_FLAG_SSE42, "SSE4.2"}, {AV_CPU_FLAG_AVX, "AVX"},    {AV_CPU_FLAG_XOP, "XOP"},
      {AV_CPU_FLAG_FMA4, "FMA4"},   {AV_CPU_FLAG_FMA3, "FMA3"},   {AV_CPU_FLAG_BMI1, "BMI1"},
      {AV_CPU_FLAG_BMI2, "BMI2"},   {AV_CPU_FLAG_AVX2, "AVX2"}};
  std::string names = lzcnt ? "LZCNT" : "";
  for (const auto& [flag, name] : features) {
    if ((cpu & flag) == 0) continue;
    if (!names.empty()) names += ',';
    names += name;
  }
  return names;
}

}  // namespace

std::optional<VideoFormat> video_format_of(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (VideoFormat f : {VideoFormat::kMp4, VideoFormat::kMkv, VideoFormat::kWebm, VideoFormat::kGif}) {
    if (ext == std::string(".") + extension_of(f)) return f;
  }
  return std::nullopt;
}

const char* extension_of(VideoFormat format) {
  switch (format) {
    case VideoFormat::kMkv: return "mkv";
    case VideoFormat::kWebm: return "webm";
    case VideoFormat::kGif: return "gif";
    default: return "mp4";
  }
}

std::unique_ptr<FrameSink> open_video(const std::filesystem::path& target, const VideoSettings& settings) {
  if (settings.format == VideoFormat::kGif) return std::make_unique<GifWriter>(target, GifSettings{settings.width, settings.height, settings.fps});
  return std::make_unique<VideoWriter>(target, settings);
}

FrameRate frame_rate_of(double fps) {
  // NTSC rates are written 29.97 & co. but mean N*1000/1001 exactly.
  for (int n : {24, 30, 48, 60, 120}) {
    const double ntsc = n * 1000.0 / 1001.0;
    if (std::abs(fps - ntsc) < 0.001 && std::abs(fps - n) > 0.001) return {n * 1000, 1001};
  }
  const AVRational q = av_d2q(fps, 100000);
  return {q.num, q.den};
}

struct VideoWriter::Impl {
  VideoSettings settings;
  const Codec& codec;
  AtomicOutput output;
  std::optional<detail::Muxer> muxer;  // Made by open(); freed after the encoders.
  AVCodecContext* encoder = nullptr;
  AVStream* stream = nullptr;  // Owned by the muxer.
  AVFrame* frame = nullptr;    // Reused for every frame.
  AVPacket* packet = nullptr;  // Reused for every packet.
  SwsContext* sws = nullptr;
  std::int64_t frames = 0;     // Frames sent; the next frame's pts (unit: 1/fps).
  int first_index = 0;
  bool finished = false;
  // The soundtrack (settings.audio), sent as the frames it accompanies are.
  AVCodecContext* audio_encoder = nullptr;
  AVStream* audio_stream = nullptr;
  AVFrame* audio_frame = nullptr;
  std::int64_t audio_sent = 0;  // Samples sent; the next audio frame's pts (unit: 1/rate).
  std::optional<detail::SubtitleStream> subtitles;  // The captions (settings.subtitles), if any.

  Impl(const std::filesystem::path& target, const VideoSettings& s)
      : settings(s), codec(codec_of(s.format)), output(target) {}

  ~Impl() {
    av_frame_free(&audio_frame);
    avcodec_free_context(&audio_encoder);
    sws_freeContext(sws);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&encoder);
    // `muxer`'s destructor then closes the file and frees the muxer, and `output`'s removes
    // the temporary unless it was committed.
  }

  [[noreturn]] void fail(ExitCode code, const std::string& what) const { encode::fail(code, what, settings.format); }
  void open();
  AVFormatContext* format() const { return muxer->context(); }
  void open_encoder(const AVCodec* av_codec);
  AVDictionary* encoder_options();
  void allocate_frame();
  void add_video_stream();
  void open_converter();
  void open_file();
  void open_audio();
  void send(const AVFrame* f);
  void send_audio_until(std::int64_t sample);
  void write_packets(AVCodecContext* from, AVStream* to);
};

void VideoWriter::Impl::open() {
  detail::quiet_libav_logging();
  const AVCodec* av_codec = avcodec_find_encoder_by_name(codec.encoder);
  if (av_codec == nullptr) {
    fail(ExitCode::kInternal, std::string("this FFmpeg build has no ") + codec.encoder +
                                  " encoder (check `systole info`; install Debian's libavcodec59)");
  }
  muxer.emplace(output, codec.muxer, codec.label);
  open_encoder(av_codec);
  open_converter();
  if (!settings.audio.empty()) open_audio();
  if (!settings.subtitles.empty()) subtitles.emplace(format(), codec.subtitle_encoder, settings.subtitles, codec.label);
  detail::add_chapters(format(), settings.chapters, codec.label);
  open_file();
  if (subtitles) subtitles->write(format());
}

namespace {

/// The colour properties the encoder writes into the stream.
void set_colorimetry(AVCodecContext& encoder, bool yuv) {
  if (yuv) {
    // Limited ("tv") range with BT.709 everywhere, matching the swscale conversion below.
    encoder.color_range = AVCOL_RANGE_MPEG;
    encoder.color_primaries = AVCOL_PRI_BT709;
    encoder.color_trc = AVCOL_TRC_BT709;
    encoder.colorspace = AVCOL_SPC_BT709;
  } else {
    // The rendered sRGB values themselves, in planes: nothing converted, nothing lost.
    encoder.color_range = AVCOL_RANGE_JPEG;
    encoder.color_primaries = AVCOL_PRI_BT709;
    encoder.color_trc = AVCOL_TRC_IEC61966_2_1;
    encoder.colorspace = AVCOL_SPC_RGB;
  }
}

}  // namespace

void VideoWriter::Impl::open_encoder(const AVCodec* av_codec) {
  encoder = avcodec_alloc_context3(av_codec);
  frame = av_frame_alloc();
  packet = av_packet_alloc();
  if (encoder == nullptr || frame == nullptr || packet == nullptr) fail(ExitCode::kInternal, "out of memory");

  const FrameRate rate = frame_rate_of(settings.fps);
  encoder->width = settings.width;
  encoder->height = settings.height;
  encoder->pix_fmt = codec.pix_fmt;
  encoder->framerate = AVRational{rate.num, rate.den};
  encoder->time_base = AVRational{rate.den, rate.num};  // One tick per frame: pts = frame number.
  encoder->sample_aspect_ratio = AVRational{1, 1};
  set_colorimetry(*encoder, codec.yuv);
  if (format()->oformat->flags & AVFMT_GLOBALHEADER) encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;

  AVDictionary* options = encoder_options();
  const int err = avcodec_open2(encoder, av_codec, &options);
  av_dict_free(&options);
  if (err < 0) fail(ExitCode::kInternal, std::string("cannot open ") + codec.encoder + ": " + av_error_text(err));
  allocate_frame();
  add_video_stream();
}

// The format's encoder settings: some set on the context, the rest returned as the
// options avcodec_open2 takes (the caller frees them).
AVDictionary* VideoWriter::Impl::encoder_options() {
  AVDictionary* options = nullptr;
  switch (settings.format) {
    case VideoFormat::kMkv:
      // Level 3 with per-slice CRCs: an archive that can tell when it has been damaged. One
      // thread: FFV1's bits do not depend on it, and the other core renders.
      encoder->thread_count = 1;
      encoder->flags |= AV_CODEC_FLAG_BITEXACT;
      av_dict_set(&options, "level", "3", 0);
      av_dict_set(&options, "slicecrc", "1", 0);
      av_dict_set(&options, "g", "1", 0);  // Every frame a key frame: any frame can be cut out.
      break;
    case VideoFormat::kWebm:
      // One thread and no row-based threading: libvpx's output then depends only on the
      // frames (it does not promise the same bits at other thread counts).
      encoder->thread_count = 1;
      encoder->flags |= AV_CODEC_FLAG_BITEXACT;
      av_dict_set_int(&options, "crf", settings.vp9_crf, 0);
      av_dict_set(&options, "b", "0", 0);  // Constant quality, no bitrate target.
      av_dict_set(&options, "deadline", "good", 0);
      av_dict_set_int(&options, "cpu-used", settings.vp9_speed, 0);
      av_dict_set(&options, "row-mt", "0", 0);
      break;
    default: {
      // CRF 0 is lossless, which x264 encodes only in the High 4:4:4 Predictive profile
      // (4:2:0 samples still): the joined segments of a bake then decode to exactly the
      // single run's frames. Every other CRF uses High, which every player decodes.
      const bool lossless = settings.crf == 0;
      encoder->profile = lossless ? FF_PROFILE_H264_HIGH_444_PREDICTIVE : FF_PROFILE_H264_HIGH;
      encoder->thread_count = settings.threads;
      av_dict_set(&options, "preset", settings.preset.c_str(), 0);
      av_dict_set(&options, "profile", lossless ? "high444" : "high", 0);
      av_dict_set_int(&options, "crf", settings.crf, 0);
      // Not x264's AVX-512 code: its macroblock-tree propagation (Debian 12's x264
      // 0.164.3095, mbtree_propagate_list_internal_avx512) takes eight macroblocks at a time,
      // so on a frame's last row it reads the costs and motion vectors of up to seven
      // macroblocks past the end of its arrays - allocation padding x264 never writes - and
      // adds what it finds there to the reference frames' costs, and so to their quantisers.
      // The bytes then followed what the heap held before: the same frames encoded twice
      // differed, rarely, on an AVX-512 machine (Formats.SameFramesGiveTheSameBytes), and
      // always when the heap was filled first (tests/encode/heap_history_test.cpp). Its
      // AVX2 code stays within the row; where the padding is zero both give the same bytes.
      if (const std::string cpu = x264_cpu_without_avx512(); !cpu.empty()) {
        av_dict_set(&options, "x264-params", ("asm=" + cpu).c_str(), 0);
      }
      break;
    }
  }
  return options;
}

// The one frame every picture is converted into, in the encoder's format and colours.
void VideoWriter::Impl::allocate_frame() {
  frame->format = encoder->pix_fmt;
  frame->width = encoder->width;
  frame->height = encoder->height;
  frame->color_range = encoder->color_range;
  frame->color_primaries = encoder->color_primaries;
  frame->color_trc = encoder->color_trc;
  frame->colorspace = encoder->colorspace;
  if (av_frame_get_buffer(frame, 0) < 0) fail(ExitCode::kInternal, "out of memory for a frame");
  // The planes' padding beyond the picture is never written by the conversion. Zeroed, so
  // no encoder can see what malloc left there. (It was once taken for the cause of two
  // encodes differing; with it left as malloc gave it, tests/encode/heap_history_test.cpp
  // still passes. The cause was x264's AVX-512 code: see encoder_options.)
  for (AVBufferRef* buffer : frame->buf) {
    if (buffer != nullptr) std::memset(buffer->data, 0, buffer->size);
  }
}

void VideoWriter::Impl::add_video_stream() {
  stream = avformat_new_stream(format(), nullptr);
  if (stream == nullptr) fail(ExitCode::kInternal, "cannot add a video stream");
  // A hint; the muxer may pick a finer one. The stream's frame rate stays unset: MP4 keeps
  // none (players derive it from sample durations), and with it set libavformat would
  // quietly patch zero packet durations, hiding a regression of send()'s fix from the tests.
  stream->time_base = encoder->time_base;
  if (avcodec_parameters_from_context(stream->codecpar, encoder) < 0) {
    fail(ExitCode::kInternal, "cannot copy the encoder parameters to the stream");
  }
}

void VideoWriter::Impl::open_converter() {
  // Accurate rounding and full chroma interpolation: the frames are smooth shading, where
  // banding and chroma fringes show. RGB24 to BGR0 is a plain reordering of bytes.
  sws = sws_getContext(settings.width, settings.height, AV_PIX_FMT_RGB24, settings.width, settings.height,
                       codec.pix_fmt, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr,
                       nullptr);
  if (sws == nullptr) fail(ExitCode::kInternal, "cannot set up the RGB conversion");
  if (!codec.yuv) return;
  // RGB in full range to BT.709 limited-range YUV. For an RGB source swscale builds its
  // RGB->YUV matrix from the destination `table`.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  constexpr int kSrcFullRange = 1, kDstLimitedRange = 0;
  if (sws_setColorspaceDetails(sws, bt709, kSrcFullRange, bt709, kDstLimitedRange, 0, 1 << 16, 1 << 16) < 0) {
    fail(ExitCode::kInternal, "swscale refused the BT.709 conversion");
  }
}

void VideoWriter::Impl::open_file() {
  std::vector<std::pair<const char*, const char*>> options;
  if (settings.format == VideoFormat::kMp4) {
    options.emplace_back("movflags", "+faststart");  // moov before mdat: plays while downloading.
  }
  muxer->write_header(options);
}

// Sends one frame (nullptr: flush) and writes every packet the encoder has ready.
void VideoWriter::Impl::send(const AVFrame* f) {
  int err = avcodec_send_frame(encoder, f);
  if (err < 0) fail(ExitCode::kInternal, std::string(codec.encoder) + " refused a frame: " + av_error_text(err));
  write_packets(encoder, stream);
}

// Writes every packet `from` has ready to stream `to`.
void VideoWriter::Impl::write_packets(AVCodecContext* from, AVStream* to) {
  const char* name = from == encoder ? codec.encoder : codec.audio_encoder;
  for (;;) {
    int err = avcodec_receive_packet(from, packet);
    if (err == AVERROR(EAGAIN) || err == AVERROR_EOF) return;
    if (err < 0) fail(ExitCode::kInternal, std::string(name) + " failed: " + av_error_text(err));
    // libavcodec 59's libx264 wrapper leaves durations at 0, which makes the last frame
    // last 0 s (a 30-frame clip at 30 fps would be 0.967 s). One frame = one tick.
    if (packet->duration == 0 && from == encoder) packet->duration = 1;
    muxer->write(packet, from->time_base, to);
  }
}

void VideoWriter::Impl::open_audio() {
  const AVCodec* av_codec = avcodec_find_encoder_by_name(codec.audio_encoder);
  if (av_codec == nullptr) {
    fail(ExitCode::kInternal, std::string("this FFmpeg build has no ") + codec.audio_encoder +
                                  " encoder for the soundtrack (install Debian's libavcodec59)");
  }
  audio_encoder = avcodec_alloc_context3(av_codec);
  audio_frame = av_frame_alloc();
  if (audio_encoder == nullptr || audio_frame == nullptr) fail(ExitCode::kInternal, "out of memory");
  // Mono float if the encoder takes it (AAC: planar float, Opus: float), else 16-bit (FLAC).
  AVSampleFormat sample_format = AV_SAMPLE_FMT_NONE;
  for (AVSampleFormat wanted : {AV_SAMPLE_FMT_FLTP, AV_SAMPLE_FMT_FLT, AV_SAMPLE_FMT_S16}) {
    for (const AVSampleFormat* f = av_codec->sample_fmts; f != nullptr && *f != AV_SAMPLE_FMT_NONE; ++f) {
      if (*f == wanted && sample_format == AV_SAMPLE_FMT_NONE) sample_format = wanted;
    }
  }
  if (sample_format == AV_SAMPLE_FMT_NONE) fail(ExitCode::kInternal, std::string(codec.audio_encoder) + " takes no sample format we write");
  audio_encoder->sample_fmt = sample_format;
  audio_encoder->sample_rate = settings.audio_rate_hz;
  av_channel_layout_default(&audio_encoder->ch_layout, 1);
  audio_encoder->time_base = AVRational{1, settings.audio_rate_hz};
  audio_encoder->bit_rate = codec.audio_bit_rate;
  // One thread and bit-exact: the same samples give the same packets.
  audio_encoder->thread_count = 1;
  audio_encoder->flags |= AV_CODEC_FLAG_BITEXACT;
  if (format()->oformat->flags & AVFMT_GLOBALHEADER) audio_encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* options = nullptr;
  if (settings.format == VideoFormat::kWebm) av_dict_set(&options, "application", "audio", 0);
  const int err = avcodec_open2(audio_encoder, av_codec, &options);
  av_dict_free(&options);
  if (err < 0) fail(ExitCode::kInternal, std::string("cannot open ") + codec.audio_encoder + ": " + av_error_text(err));

  audio_frame->format = audio_encoder->sample_fmt;
  audio_frame->sample_rate = audio_encoder->sample_rate;
  av_channel_layout_copy(&audio_frame->ch_layout, &audio_encoder->ch_layout);
  audio_frame->nb_samples = audio_encoder->frame_size > 0 ? audio_encoder->frame_size : 1024;
  if (av_frame_get_buffer(audio_frame, 0) < 0) fail(ExitCode::kInternal, "out of memory for an audio frame");
  for (AVBufferRef* buffer : audio_frame->buf) {
    if (buffer != nullptr) std::memset(buffer->data, 0, buffer->size);  // No stray bytes reach the encoder.
  }
  audio_stream = avformat_new_stream(format(), nullptr);
  if (audio_stream == nullptr) fail(ExitCode::kInternal, "cannot add an audio stream");
  audio_stream->time_base = audio_encoder->time_base;
  // The encoder's priming samples (AAC 1024, Opus 312) go with the parameters as
  // initial_padding: the MP4 muxer writes them as the edit list's media time, the WebM muxer
  // as CodecDelay, so a player drops them and sample 0 plays with frame 0.
  if (avcodec_parameters_from_context(audio_stream->codecpar, audio_encoder) < 0) {
    fail(ExitCode::kInternal, "cannot copy the audio encoder parameters to the stream");
  }
}

// Sends whole audio frames of the soundtrack up to sample `until` (and a last short frame
// when `until` is its end).
void VideoWriter::Impl::send_audio_until(std::int64_t until) {
  const auto total = static_cast<std::int64_t>(settings.audio.size());
  until = std::min(until, total);
  const int frame_size = audio_encoder->frame_size > 0 ? audio_encoder->frame_size : 1024;
  while (audio_sent < until && (audio_sent + frame_size <= until || until == total)) {
    const int n = static_cast<int>(std::min<std::int64_t>(frame_size, total - audio_sent));
    int err = av_frame_make_writable(audio_frame);
    if (err < 0) fail(ExitCode::kInternal, "cannot get a writable audio frame: " + av_error_text(err));
    audio_frame->nb_samples = n;
    const float* src = settings.audio.data() + audio_sent;
    if (audio_encoder->sample_fmt == AV_SAMPLE_FMT_S16) {
      auto* dst = reinterpret_cast<std::int16_t*>(audio_frame->data[0]);
      for (int i = 0; i < n; ++i) dst[i] = static_cast<std::int16_t>(std::lround(std::clamp(src[i], -1.0f, 1.0f) * 32767.0f));
    } else {  // Mono: planar and packed float are the same bytes.
      std::memcpy(audio_frame->data[0], src, sizeof(float) * static_cast<std::size_t>(n));
    }
    audio_frame->pts = audio_sent;
    err = avcodec_send_frame(audio_encoder, audio_frame);
    if (err < 0) fail(ExitCode::kInternal, std::string(codec.audio_encoder) + " refused a frame: " + av_error_text(err));
    audio_sent += n;
    write_packets(audio_encoder, audio_stream);
  }
}

VideoWriter::VideoWriter(const std::filesystem::path& target, const VideoSettings& settings) {
  validate(settings);
  impl_ = std::make_unique<Impl>(target, settings);
  impl_->open();
}

VideoWriter::~VideoWriter() = default;

int VideoWriter::frame_count() const { return static_cast<int>(impl_->frames); }

void VideoWriter::write(const Image& image, int frame_index) {
  Impl& m = *impl_;
  if (m.finished) m.fail(ExitCode::kInternal, "write() after finish()");
  const VideoSettings& s = m.settings;
  if (image.width != s.width || image.height != s.height ||
      image.rgb.size() != static_cast<std::size_t>(s.width) * s.height * 3) {
    m.fail(ExitCode::kInternal, "frame " + std::to_string(frame_index) + " is " + std::to_string(image.width) + "x" +
                                  std::to_string(image.height) + ", the video is " + std::to_string(s.width) +
                                  "x" + std::to_string(s.height));
  }
  if (m.frames == 0) {
    m.first_index = frame_index;
  } else if (frame_index != m.first_index + m.frames) {
    m.fail(ExitCode::kInternal, "frame " + std::to_string(frame_index) + " arrived; expected frame " +
                                  std::to_string(m.first_index + m.frames));
  }
  // The encoder may still hold a reference to the buffers; this copies only then.
  int err = av_frame_make_writable(m.frame);
  if (err < 0) m.fail(ExitCode::kInternal, "cannot get a writable frame: " + av_error_text(err));
  const std::uint8_t* src[1] = {image.rgb.data()};
  const int src_stride[1] = {s.width * 3};
  sws_scale(m.sws, src, src_stride, 0, s.height, m.frame->data, m.frame->linesize);
  m.frame->pts = m.frames;
  m.send(m.frame);
  ++m.frames;
  // The sound of this frame's time: everything before the next frame starts.
  if (m.audio_encoder != nullptr) {
    const FrameRate rate = frame_rate_of(s.fps);
    m.send_audio_until(av_rescale(m.frames, static_cast<std::int64_t>(rate.den) * s.audio_rate_hz, rate.num));
  }
}

void VideoWriter::finish() {
  Impl& m = *impl_;
  if (m.finished) m.fail(ExitCode::kInternal, "finish() called twice");
  if (m.frames == 0) m.fail(ExitCode::kInternal, "no frame was written to '" + m.output.target().string() + "'");
  m.send(nullptr);
  if (m.audio_encoder != nullptr) {
    m.send_audio_until(static_cast<std::int64_t>(m.settings.audio.size()));
    const int err = avcodec_send_frame(m.audio_encoder, nullptr);
    if (err < 0) m.fail(ExitCode::kInternal, "cannot flush the audio encoder: " + av_error_text(err));
    m.write_packets(m.audio_encoder, m.audio_stream);
  }
  m.muxer->finish();
  m.output.commit();
  m.finished = true;
}

}  // namespace systole::encode
