#include "audio/wav.h"

#include <algorithm>
#include <cmath>

#include "common/atomic_output.h"

namespace systole::audio {
namespace {

void put_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}
void put_u16(std::string& out, std::uint16_t v) {
  out.push_back(static_cast<char>(v & 0xff));
  out.push_back(static_cast<char>(v >> 8));
}

}  // namespace

std::int16_t to_pcm16(float x) {
  const double v = std::clamp(static_cast<double>(x), -1.0, 1.0) * 32767.0;
  return static_cast<std::int16_t>(std::lround(v));
}

std::string wav_bytes(const Soundtrack& track) {
  const auto data_bytes = static_cast<std::uint32_t>(2 * track.samples.size());
  std::string out;
  out.reserve(44 + data_bytes);
  out += "RIFF";
  put_u32(out, 36 + data_bytes);
  out += "WAVEfmt ";
  put_u32(out, 16);
  put_u16(out, 1);  // PCM
  put_u16(out, 1);  // mono
  put_u32(out, static_cast<std::uint32_t>(track.sample_rate_hz));
  put_u32(out, static_cast<std::uint32_t>(2 * track.sample_rate_hz));  // bytes per second
  put_u16(out, 2);   // block align
  put_u16(out, 16);  // bits per sample
  out += "data";
  put_u32(out, data_bytes);
  for (float x : track.samples) put_u16(out, static_cast<std::uint16_t>(to_pcm16(x)));
  return out;
}

void write_wav(const std::filesystem::path& target, const Soundtrack& track) {
  write_file_atomically(target, wav_bytes(track));
}

}  // namespace systole::audio
