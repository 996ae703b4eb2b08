#pragma once
// Every exported file appears whole or not at all (common/atomic_output.h): written to a
// temporary beside it and renamed when complete.

#include <filesystem>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string_view>

namespace systole::exporter {

/// Writes `bytes` to `file` atomically. Throws Error(kCannotCreate) when the folder cannot
/// take it, Error(kIoError) when writing fails part-way (nothing is left behind).
void write_file_atomically(const std::filesystem::path& file, std::string_view bytes);

/// The same, the contents streamed by `fill` (a large file need not sit in memory whole).
void write_stream_atomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& fill);

/// Little- and big-endian 32-bit values, byte by byte (the formats fix the order, not the host).
void put_le32(std::ostream& out, std::uint32_t bits);
void put_be32(std::ostream& out, std::uint32_t bits);
std::uint32_t float_bits(float v);

}  // namespace systole::exporter
