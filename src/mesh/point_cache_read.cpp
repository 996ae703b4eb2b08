#include "mesh/point_cache_read.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>

#include "common/error.h"
#include "common/input_file.h"

namespace systole::mesh {
namespace fs = std::filesystem;
namespace {

constexpr std::size_t kPc2Header = 32;  // signature 12, version, points, start, rate, samples
constexpr std::size_t kMddHeader = 8;   // frames, points
constexpr std::size_t kPointBytes = 12;  // float32 x y z

[[noreturn]] void data_error(const fs::path& file, const std::string& what) {
  throw Error(ExitCode::kDataError, file.string() + ": " + what);
}

// ---------------------------------------------------------------------------------------
// The rest mesh: an OBJ read line by line, as written.

/// The whitespace-separated words of a line.
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

/// Where an OBJ line is, for messages: "heart.obj:12".
std::string at_line(const fs::path& obj, int line) { return obj.string() + ":" + std::to_string(line); }

/// A `v` line's position.
Eigen::Vector3d obj_vertex(const std::vector<std::string_view>& w, const fs::path& obj, int line) {
  if (w.size() < 4) throw Error(ExitCode::kDataError, at_line(obj, line) + ": a vertex needs x y z, this `v` line has " + std::to_string(w.size() - 1) + " numbers");
  Eigen::Vector3d p;
  for (int k = 0; k < 3; ++k) {
    const std::string text(w[static_cast<std::size_t>(k) + 1]);
    char* end = nullptr;
    p[k] = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0') {
      throw Error(ExitCode::kDataError, at_line(obj, line) + ": '" + text + "' is not a number (expected `v x y z`)");
    }
    if (!std::isfinite(p[k])) throw Error(ExitCode::kDataError, at_line(obj, line) + ": vertex coordinate '" + text + "' is not finite");
  }
  return p;
}

/// A face corner's vertex (the number before any '/'), 0-based; `vertices` come before it.
int obj_corner(std::string_view word, std::size_t vertices, const fs::path& obj, int line) {
  const std::string_view number = word.substr(0, word.find('/'));
  long long index = 0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), index);
  if (ec != std::errc() || end != number.data() + number.size() || index == 0) {
    throw Error(ExitCode::kDataError, at_line(obj, line) + ": face corner '" + std::string(word) +
                                          "' is not a vertex index (expected 1.." + std::to_string(vertices) +
                                          " or -1..-" + std::to_string(vertices) + ", optionally with /vt/vn)");
  }
  const long long resolved = index > 0 ? index - 1 : static_cast<long long>(vertices) + index;
  if (resolved < 0 || resolved >= static_cast<long long>(vertices)) {
    throw Error(ExitCode::kDataError, at_line(obj, line) + ": face corner " + std::to_string(index) + " is out of range: " +
                                          std::to_string(vertices) + " vertices come before this line");
  }
  return static_cast<int>(resolved);
}

/// The part named `name`, added when new.
int part_index(std::vector<std::string>& parts, const std::string& name) {
  const auto it = std::find(parts.begin(), parts.end(), name);
  if (it != parts.end()) return static_cast<int>(it - parts.begin());
  parts.push_back(name);
  return static_cast<int>(parts.size()) - 1;
}

/// The rest of a line after its first word, trimmed: an `o` or `g` line's name.
std::string name_after_keyword(std::string_view line) {
  const auto first = line.find_first_not_of(" \t");
  const auto space = line.find_first_of(" \t", first);
  if (space == std::string_view::npos) return {};
  const auto begin = line.find_first_not_of(" \t", space);
  if (begin == std::string_view::npos) return {};
  const auto end = line.find_last_not_of(" \t");
  return std::string(line.substr(begin, end - begin + 1));
}

/// Fills `out`'s rest, triangles, parts and vertex_part from the OBJ.
void read_obj(const fs::path& obj, AnimatedSurface& out) {
  std::ifstream in(obj, std::ios::binary);
  if (!in) throw Error(ExitCode::kNoInput, obj.string() + ": cannot open the rest mesh");
  std::vector<int> triangle_part;
  int part = -1;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const auto w = words(text);
    if (w.empty()) continue;
    if (w[0] == "v") {
      out.rest.push_back(obj_vertex(w, obj, line));
    } else if (w[0] == "f") {
      if (w.size() < 4) throw Error(ExitCode::kDataError, at_line(obj, line) + ": a face needs at least 3 corners, this one has " + std::to_string(w.size() - 1));
      std::vector<int> corners;
      for (std::size_t k = 1; k < w.size(); ++k) corners.push_back(obj_corner(w[k], out.rest.size(), obj, line));
      // A polygon as a fan from its first corner: the order (and so the facing) kept.
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        out.triangles.emplace_back(corners[0], corners[k], corners[k + 1]);
        triangle_part.push_back(part);
      }
    } else if (w[0] == "o" || w[0] == "g") {
      const std::string name = name_after_keyword(text);
      part = part_index(out.parts, name.empty() ? "default" : name);
    }
  }
  if (in.bad()) throw Error(ExitCode::kIoError, obj.string() + ": reading the rest mesh failed part-way");
  if (out.parts.empty()) return;
  // A vertex on the border of two parts is in the first one's: the file's order decides.
  out.vertex_part.assign(out.rest.size(), -1);
  for (std::size_t t = 0; t < out.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      int& p = out.vertex_part[static_cast<std::size_t>(out.triangles[t][k])];
      if (p < 0) p = triangle_part[t];
    }
  }
}

// ---------------------------------------------------------------------------------------
// The cache: its bytes decoded by hand, so the host's byte order never shows.

std::uint32_t le32(const char* p) {
  unsigned char b[4];
  std::memcpy(b, p, 4);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

std::uint32_t be32(const char* p) {
  unsigned char b[4];
  std::memcpy(b, p, 4);
  return std::uint32_t(b[3]) | std::uint32_t(b[2]) << 8 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[0]) << 24;
}

float as_float(std::uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

std::int32_t as_int(std::uint32_t bits) {
  std::int32_t i;
  std::memcpy(&i, &bits, 4);
  return i;
}

/// The file's first `n` bytes, or all of it when shorter.
std::string read_head(const fs::path& file, std::size_t n) {
  std::ifstream in(file, std::ios::binary);
  std::string head(n, '\0');
  in.read(head.data(), static_cast<std::streamsize>(n));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

/// The whole file: called once its header's counts are checked against its size, so this
/// allocates what is on disk, never what a header claims.
std::string read_all(const fs::path& file, std::uintmax_t size) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (static_cast<std::uintmax_t>(in.gcount()) != size) throw Error(ExitCode::kIoError, file.string() + ": reading the point cache failed part-way");
  return bytes;
}

/// Checks that `size` bytes hold exactly a header of `header` bytes, `frames` x 4 bytes of
/// times (MDD; 0 for PC2) and `frames` x `points` positions; the products are formed only
/// once they are known to fit, so a header claiming 2^31 points costs nothing.
void check_size(const fs::path& file, std::uintmax_t size, std::size_t header, std::size_t time_bytes,
                std::uint64_t frames, std::uint64_t points, const char* frame_word) {
  const std::string counts = std::to_string(points) + " points x " + std::to_string(frames) + " " + frame_word;
  const std::uint64_t fixed = header + time_bytes * frames;
  if (size < fixed || (size - fixed) / kPointBytes / frames < points) {
    data_error(file, "the header says " + counts + ", but the file holds only " + std::to_string(size) +
                         " bytes: a cache cut short (an export interrupted, or a copy incomplete)");
  }
  const std::uint64_t expected = fixed + points * frames * kPointBytes;
  if (size != expected) {
    data_error(file, "the header says " + counts + " (" + std::to_string(expected) + " bytes), but the file holds " +
                         std::to_string(size) + ": the header does not describe the data");
  }
}

/// Decodes `frames` x `points` positions starting at `offset`, refusing non-finite ones.
std::vector<std::vector<Eigen::Vector3d>> decode_poses(const std::string& bytes, std::size_t offset, std::size_t frames,
                                                       std::size_t points, bool big_endian, const fs::path& file,
                                                       const char* frame_word) {
  std::vector<std::vector<Eigen::Vector3d>> poses(frames, std::vector<Eigen::Vector3d>(points));
  const char* p = bytes.data() + offset;
  for (std::size_t f = 0; f < frames; ++f) {
    for (std::size_t v = 0; v < points; ++v) {
      for (int k = 0; k < 3; ++k, p += 4) {
        const float x = as_float(big_endian ? be32(p) : le32(p));
        if (!std::isfinite(x)) {
          data_error(file, std::string(frame_word) + " " + std::to_string(f) + ", point " + std::to_string(v) +
                               " has a non-finite coordinate (" + std::to_string(x) + ")");
        }
        poses[f][v][k] = x;
      }
    }
  }
  return poses;
}

/// The cache's point count against the OBJ's `v` lines, before the poses are allocated.
void check_points(const fs::path& cache, const fs::path& obj, std::uint64_t points, std::size_t vertices) {
  if (points != vertices) {
    data_error(cache, std::to_string(points) + " points per frame, but its rest mesh " + obj.string() + " has " +
                          std::to_string(vertices) +
                          " vertices (`v` lines): the cache belongs to another mesh, or the OBJ was re-saved welded or "
                          "reordered; a cache indexes the OBJ's vertices in order");
  }
}

/// A header count read as int32: at least 1.
std::uint64_t positive_count(std::uint32_t bits, const fs::path& file, const char* what) {
  const std::int32_t n = as_int(bits);
  if (n <= 0) data_error(file, "the header says " + std::to_string(n) + " " + what + "; expected at least 1");
  return static_cast<std::uint64_t>(n);
}

void read_pc2(const fs::path& cache, const fs::path& obj, AnimatedSurface& out) {
  const std::uintmax_t size = fs::file_size(cache);
  const std::string head = read_head(cache, kPc2Header);
  if (head.size() < kPc2Header || std::memcmp(head.data(), "POINTCACHE2\0", 12) != 0) {
    data_error(cache, "not a PC2 point cache: it does not start with the signature POINTCACHE2 (and its 32-byte header)");
  }
  const std::int32_t version = as_int(le32(head.data() + 12));
  if (version != 1) data_error(cache, "PC2 version " + std::to_string(version) + "; expected 1");
  const std::uint64_t points = positive_count(le32(head.data() + 16), cache, "points");
  const double start = as_float(le32(head.data() + 20)), rate = as_float(le32(head.data() + 24));
  if (as_int(le32(head.data() + 28)) == 0) data_error(cache, "the cache holds no samples (its header says 0)");
  const std::uint64_t samples = positive_count(le32(head.data() + 28), cache, "samples");
  if (!std::isfinite(start)) data_error(cache, "the start frame is not finite");
  if (!(std::isfinite(rate) && rate > 0)) data_error(cache, "the sample rate is " + std::to_string(rate) + " frames; expected a number above 0");
  check_size(cache, size, kPc2Header, 0, samples, points, "samples");
  read_obj(obj, out);
  check_points(cache, obj, points, out.rest.size());
  out.poses = decode_poses(read_all(cache, size), kPc2Header, samples, points, false, cache, "sample");
  for (std::uint64_t k = 0; k < samples; ++k) out.times.push_back(start + static_cast<double>(k) * rate);
  out.duration = static_cast<double>(samples) * rate;
  out.in_seconds = false;
}

void read_mdd(const fs::path& cache, const fs::path& obj, AnimatedSurface& out) {
  const std::uintmax_t size = fs::file_size(cache);
  const std::string head = read_head(cache, kMddHeader);
  if (head.size() < kMddHeader) data_error(cache, "shorter than an MDD header (8 bytes: frames and points)");
  if (as_int(be32(head.data())) == 0) data_error(cache, "the cache holds no frames (its header says 0)");
  const std::uint64_t frames = positive_count(be32(head.data()), cache, "frames");
  const std::uint64_t points = positive_count(be32(head.data() + 4), cache, "points");
  check_size(cache, size, kMddHeader, 4, frames, points, "frames");
  read_obj(obj, out);
  check_points(cache, obj, points, out.rest.size());
  const std::string bytes = read_all(cache, size);
  for (std::uint64_t f = 0; f < frames; ++f) {
    const double t = as_float(be32(bytes.data() + kMddHeader + 4 * f));
    if (!std::isfinite(t)) data_error(cache, "frame " + std::to_string(f) + "'s time is not finite");
    if (f > 0 && t <= out.times.back()) {
      data_error(cache, "frame " + std::to_string(f) + "'s time " + std::to_string(t) + " s is not after frame " +
                            std::to_string(f - 1) + "'s " + std::to_string(out.times.back()) + " s; expected increasing times");
    }
    out.times.push_back(t);
  }
  out.poses = decode_poses(bytes, kMddHeader + 4 * frames, frames, points, true, cache, "frame");
  // The last frame lasts as long as the one before it.
  const std::size_t n = out.times.size();
  out.duration = out.times[n - 1] + (n > 1 ? out.times[n - 1] - out.times[n - 2] : 0.0);
  out.in_seconds = true;
}

std::string lower_extension(const fs::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

AnimatedSurface read_point_cache(const fs::path& cache, const fs::path& obj) {
  const std::string ext = lower_extension(cache);
  if (ext != ".pc2" && ext != ".mdd") {
    data_error(cache, "not a point cache by its extension '" + cache.extension().string() + "'; expected .pc2 or .mdd");
  }
  if (const auto reason = unreadable_file_reason(cache)) {
    throw Error(ExitCode::kNoInput, cache.string() + ": cannot read the point cache: it is " + *reason);
  }
  fs::path rest_mesh = obj;
  if (rest_mesh.empty()) rest_mesh = fs::path(cache).replace_extension(".obj");
  if (const auto reason = unreadable_file_reason(rest_mesh)) {
    throw Error(ExitCode::kNoInput,
                cache.string() + ": cannot read its rest mesh " + rest_mesh.string() + ": it is " + *reason +
                    " (a point cache holds only positions; `systole export` writes the OBJ beside it with the same "
                    "name; give the rest mesh's path when it is elsewhere)");
  }
  AnimatedSurface out;
  out.file = cache.string();
  if (ext == ".pc2") {
    read_pc2(cache, rest_mesh, out);
  } else {
    read_mdd(cache, rest_mesh, out);
  }
  return out;
}

}  // namespace systole::mesh
