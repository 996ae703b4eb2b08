#include "export/write_file.h"

#include <bit>
#include <fstream>

#include "common/atomic_output.h"
#include "common/error.h"

namespace systole::exporter {

void write_stream_atomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& fill) {
  AtomicOutput output(file);
  {
    std::ofstream out(output.temp_path(), std::ios::binary);
    if (!out) throw Error(ExitCode::kCannotCreate, "cannot create '" + file.string() + "'");
    fill(out);
    if (!out.flush()) throw Error(ExitCode::kIoError, "cannot write '" + file.string() + "' (disk full?)");
  }
  output.commit();
}

void write_file_atomically(const std::filesystem::path& file, std::string_view bytes) {
  write_stream_atomically(file, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

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
