#include "world/bake.h"

#include <bit>
#include <cstring>

#include "common/atomic_output.h"
#include "common/error.h"
#include "common/hash.h"
#include "scene/content_hash.h"

namespace systole::world {
namespace fs = std::filesystem;

// The format is little-endian; we write host order, so say where that holds.
static_assert(std::endian::native == std::endian::little, "bake files are written in host (little-endian) order");

namespace {

constexpr char kMagic[8] = {'S', 'Y', 'S', 'B', 'A', 'K', 'E', '\n'};

/// An ofstream that hashes what it writes.
class HashedWriter {
 public:
  explicit HashedWriter(const fs::path& file) : out_(file, std::ios::binary), file_(file) {}
  template <class T>
  void put(const T& value) { bytes(&value, sizeof value); }
  void bytes(const void* data, std::size_t n) {
    hash_.update(data, n);
    out_.write(static_cast<const char*>(data), static_cast<std::streamsize>(n));
  }
  void finish() {
    const std::uint64_t sum = hash_.value();
    out_.write(reinterpret_cast<const char*>(&sum), sizeof sum);
    if (!out_.flush()) throw Error(ExitCode::kIoError, "cannot write '" + file_.string() + "'");
  }

 private:
  std::ofstream out_;
  fs::path file_;
  Fnv1a64 hash_;
};

[[noreturn]] void corrupt(const fs::path& file, const std::string& why) {
  throw Error(ExitCode::kDataError, file.string() + ": not a usable bake file: " + why);
}

}  // namespace

struct BakeWriter::Impl {
  Impl(const fs::path& file) : output(file), out(output.temp_path()) {}
  AtomicOutput output;
  HashedWriter out;
};

BakeWriter::BakeWriter(const fs::path& file, const scene::Scene& scene, const World& world)
    : impl_(std::make_unique<Impl>(file)) {
  HashedWriter& out = impl_->out;
  out.bytes(kMagic, sizeof kMagic);
  out.put(kBakeFormatVersion);
  out.put(static_cast<std::uint32_t>(world.organs.size()));
  out.put(static_cast<std::uint32_t>(scene.output.frame_count()));
  out.put(std::uint32_t{0});  // Reserved: flags.
  out.put(scene.output.fps);
  out.put(scene::scene_content_hash(scene));
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const std::string& name = scene.organs[o].name;
    out.put(static_cast<std::uint32_t>(world.organs[o].geometry.mesh.surface.positions.size()));
    out.put(static_cast<std::uint32_t>(name.size()));
    out.bytes(name.data(), name.size());
  }
}

BakeWriter::~BakeWriter() = default;

void BakeWriter::write(const Eigen::Matrix3Xd& positions) {
  impl_->out.bytes(positions.data(), sizeof(double) * positions.size());
}

void BakeWriter::commit() {
  impl_->out.finish();
  impl_->output.commit();
}

BakeReader::BakeReader(const fs::path& file) : file_(file), in_(file, std::ios::binary) {
  if (!in_) throw Error(ExitCode::kNoInput, "cannot read bake file '" + file.string() + "'");
  // Verify the checksum over everything before the last 8 bytes, streaming.
  std::error_code ec;
  const auto size = static_cast<std::streamoff>(fs::file_size(file, ec));
  if (ec || size < static_cast<std::streamoff>(sizeof kMagic + 8)) corrupt(file, "too short");
  Fnv1a64 hash;
  std::vector<char> buf(1 << 20);
  for (std::streamoff left = size - 8; left > 0;) {
    const auto n = static_cast<std::streamsize>(std::min<std::streamoff>(left, buf.size()));
    if (!in_.read(buf.data(), n)) corrupt(file, "cannot read");
    hash.update(buf.data(), static_cast<std::size_t>(n));
    left -= n;
  }
  std::uint64_t stored = 0;
  in_.read(reinterpret_cast<char*>(&stored), sizeof stored);
  in_.seekg(0);

  auto get = [&](auto& value) {
    if (!in_.read(reinterpret_cast<char*>(&value), sizeof value)) corrupt(file, "truncated header");
  };
  char magic[sizeof kMagic];
  if (!in_.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0) {
    corrupt(file, "wrong magic (made by `systole bake`?)");
  }
  std::uint32_t version = 0, organs = 0, frames = 0, flags = 0;
  get(version);
  if (version != kBakeFormatVersion) {
    corrupt(file, "format version " + std::to_string(version) + ", this Systole reads version " +
                      std::to_string(kBakeFormatVersion) + " (bake again)");
  }
  if (stored != hash.value()) corrupt(file, "checksum mismatch (damaged or truncated)");
  get(organs);
  get(frames);
  get(flags);
  get(info_.fps);
  get(info_.scene_hash);
  info_.frame_count = static_cast<int>(frames);
  checksum_ = stored;
  std::streamoff offset = 0;
  for (std::uint32_t o = 0; o < organs; ++o) {
    std::uint32_t vertices = 0, name_bytes = 0;
    get(vertices);
    get(name_bytes);
    if (name_bytes > 4096) corrupt(file, "organ name too long");
    std::string name(name_bytes, '\0');
    if (!in_.read(name.data(), name_bytes)) corrupt(file, "truncated header");
    info_.organs.push_back({name, static_cast<int>(vertices)});
    organ_offset_.push_back(offset);
    offset += static_cast<std::streamoff>(3 * sizeof(double)) * vertices;
  }
  frame_bytes_ = offset;
  payload_offset_ = in_.tellg();
  if (payload_offset_ + frame_bytes_ * frames + 8 != size) corrupt(file, "size does not match its header");
}

void BakeReader::check_matches(const scene::Scene& scene, const World& world) const {
  auto mismatch = [&](const std::string& what) {
    throw Error(ExitCode::kDataError, file_.string() + " does not fit " + scene.path + ": " + what +
                                          " (bake the scene again after changing its timing or organs)");
  };
  if (info_.fps != scene.output.fps) mismatch("baked at " + std::to_string(info_.fps) + " fps");
  if (info_.frame_count != scene.output.frame_count()) {
    mismatch("it holds " + std::to_string(info_.frame_count) + " frames, the scene has " +
             std::to_string(scene.output.frame_count()));
  }
  if (info_.organs.size() != world.organs.size()) mismatch("a different number of organs");
  for (std::size_t o = 0; o < world.organs.size(); ++o) {
    const auto& baked = info_.organs[o];
    const int vertices = static_cast<int>(world.organs[o].geometry.mesh.surface.positions.size());
    if (baked.name != scene.organs[o].name || baked.vertex_count != vertices) {
      mismatch("organ " + std::to_string(o) + " is '" + baked.name + "' with " + std::to_string(baked.vertex_count) +
               " vertices, the scene's is '" + scene.organs[o].name + "' with " + std::to_string(vertices));
    }
  }
}

void BakeReader::read(int frame, int organ, Eigen::Matrix3Xd& positions) {
  positions.resize(3, info_.organs[organ].vertex_count);
  in_.seekg(payload_offset_ + frame_bytes_ * frame + organ_offset_[organ]);
  if (!in_.read(reinterpret_cast<char*>(positions.data()), static_cast<std::streamsize>(sizeof(double) * positions.size()))) {
    throw Error(ExitCode::kIoError, "cannot read frame " + std::to_string(frame) + " from '" + file_.string() + "'");
  }
}

}  // namespace systole::world
