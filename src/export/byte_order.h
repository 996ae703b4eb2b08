#pragma once
// The byte order the point-cache formats fix (PC2 little-endian, MDD big-endian), written
// byte by byte so the host's order never shows.

#include <cstdint>
#include <ostream>

namespace systole::exporter {

/// Little- and big-endian 32-bit values, byte by byte.
void put_le32(std::ostream& out, std::uint32_t bits);
void put_be32(std::ostream& out, std::uint32_t bits);
/// A float's IEEE 754 bits, to write with put_le32 / put_be32.
std::uint32_t float_bits(float v);

}  // namespace systole::exporter
