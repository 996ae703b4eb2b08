#pragma once
// A soundtrack as a WAV file (RIFF, 16-bit PCM, mono), written whole or not at all.

#include <cstdint>
#include <filesystem>
#include <string>

#include "audio/soundtrack.h"

namespace systole::audio {

/// The 16-bit sample of a float in [-1, 1]: round(x * 32767), clamped. unit: 1
std::int16_t to_pcm16(float x);

/// The bytes of a WAV file holding `track`.
std::string wav_bytes(const Soundtrack& track);

/// Writes `track` to `target` through a temporary file and a rename (common/atomic_output.h).
/// Throws Error(kCannotCreate) or Error(kIoError).
void write_wav(const std::filesystem::path& target, const Soundtrack& track);

}  // namespace systole::audio
