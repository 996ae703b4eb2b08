#include "batch/manifest.h"

#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>
#include <vector>

#include "common/atomic_output.h"
#include "common/error.h"
#include "common/hash.h"
#include "common/json.h"

namespace systole::batch {
namespace fs = std::filesystem;

namespace {

/// The value of `"name": ` in our own manifest text (a string's contents, or a number).
std::string field(const std::string& text, const std::string& name) {
  const std::string tag = json_quote(name) + ": ";
  const auto at = text.find(tag);
  if (at == std::string::npos) return {};
  auto begin = at + tag.size();
  const bool quoted = begin < text.size() && text[begin] == '"';
  if (quoted) ++begin;
  const auto end = text.find_first_of(quoted ? "\"" : ",\n}", begin);
  return end == std::string::npos ? std::string() : text.substr(begin, end - begin);
}

/// FNV-1a over the file's bytes, or nullopt if it cannot be read.
std::optional<std::uint64_t> file_checksum(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  Fnv1a64 hash;
  std::vector<char> buffer(1 << 20);
  while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0) {
    hash.update(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) return std::nullopt;
  return hash.value();
}

}  // namespace

std::uint64_t JobIdentity::key() const {
  Fnv1a64 hash;
  // Each field on its own line, so no two different jobs concatenate to the same text.
  hash.update(std::string("systole ") + SYSTOLE_VERSION + "\nscene " + to_hex(scene_hash) + "\n");
  for (const auto& o : overrides) hash.update("-D " + o + "\n");
  hash.update("frames " + frames + "\nbake " + to_hex(bake_checksum) + "\n");
  return hash.value();
}

fs::path manifest_path(const fs::path& video) { return fs::path(video.string() + ".json"); }

bool up_to_date(const fs::path& video, const JobIdentity& job) {
  std::error_code ec;
  const auto bytes = fs::file_size(video, ec);
  if (ec) return false;
  std::ifstream in(manifest_path(video));
  if (!in) return false;
  std::stringstream text;
  text << in.rdbuf();
  if (field(text.str(), "job_key") != to_hex(job.key()) || field(text.str(), "video_bytes") != std::to_string(bytes)) {
    return false;
  }
  const auto checksum = file_checksum(video);
  return checksum && field(text.str(), "video_checksum") == to_hex(*checksum);
}

void write_manifest(const fs::path& video, const JobIdentity& job) {
  std::ostringstream json;
  json << "{\n  \"format\": \"systole-job-manifest-1\",\n"
       << "  \"job_key\": " << json_quote(to_hex(job.key())) << ",\n"
       << "  \"systole_version\": " << json_quote(SYSTOLE_VERSION) << ",\n"
       << "  \"scene\": " << json_quote(job.scene_path) << ",\n"
       << "  \"scene_hash\": " << json_quote(to_hex(job.scene_hash)) << ",\n"
       << "  \"overrides\": [";
  for (std::size_t i = 0; i < job.overrides.size(); ++i) json << (i ? ", " : "") << json_quote(job.overrides[i]);
  json << "],\n  \"frames\": " << json_quote(job.frames.empty() ? "all" : job.frames) << ",\n"
       << "  \"bake_checksum\": " << json_quote(job.bake_checksum ? to_hex(job.bake_checksum) : "") << ",\n"
       << "  \"video\": " << json_quote(video.filename().string()) << ",\n"
       << "  \"video_bytes\": " << fs::file_size(video) << ",\n"
       << "  \"video_checksum\": " << json_quote(to_hex(file_checksum(video).value_or(0))) << "\n}\n";
  AtomicOutput out(manifest_path(video));
  {
    std::ofstream file(out.temp_path(), std::ios::binary);
    file << json.str();
    if (!file.flush()) throw Error(ExitCode::kIoError, "cannot write '" + out.temp_path().string() + "'");
  }
  out.commit();
}

}  // namespace systole::batch
