#include "export/byte_order.h"

#include <bit>

namespace systole::exporter {

void put_le32(std::ostream& out, std::uint32_t v) {
  const char b[4] = {char(v & 0xff), char((v >> 8) & 0xff), char((v >> 16) & 0xff), char(v >> 24)};
  out.write(b, 4);
}

void put_be32(std::ostream& out, std::uint32_t v) {
  const char b[4] = {char(v >> 24), char((v >> 16) & 0xff), char((v >> 8) & 0xff), char(v & 0xff)};
  out.write(b, 4);
}

std::uint32_t float_bits(float v) { return std::bit_cast<std::uint32_t>(v); }

}  // namespace systole::exporter
