#include "export/exporter.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "common/error.h"
#include "export/gltf.h"
#include "export/html.h"
#include "export/point_cache.h"
#include "export/usd.h"
#include "export/vtk.h"

namespace systole::exporter {
namespace fs = std::filesystem;

namespace {

struct Known {
  const char* extension;
  FileFormat format;
};
constexpr Known kKnown[] = {{".glb", FileFormat::kGlb},   {".gltf", FileFormat::kGltf}, {".pc2", FileFormat::kPc2},
                            {".mdd", FileFormat::kMdd},   {".pvd", FileFormat::kPvd},   {".usda", FileFormat::kUsda},
                            {".html", FileFormat::kHtml}};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string megabytes(const fs::path& file) {
  std::error_code ec;
  const auto bytes = fs::file_size(file, ec);
  char text[64];
  std::snprintf(text, sizeof text, "%.2f MB", ec ? 0.0 : double(bytes) / 1e6);
  return text;
}

/// Below a nanometre of RMS motion an organ is still: what moves is rounding, and a share of it
/// would be a figure about nothing.
constexpr double kStill_m = 1e-9;

std::string morph_report(const Recording& rec, const std::vector<MorphAnimation>& morphs, const ExportOptions& options) {
  std::string text;
  char line[256];
  if (options.encoding == Encoding::kCompact) {
    std::snprintf(line, sizeof line,
                  "compact loop of %d frames (%.3f s, whole cycles after settling: simulated frames %d to %d)",
                  rec.frame_count(), rec.frame_count() / rec.fps, rec.start_frame, rec.start_frame + rec.frame_count() - 1);
  } else {
    std::snprintf(line, sizeof line, "every frame a morph target, %d frames (%.3f s)%s", rec.frame_count(),
                  rec.frame_count() / rec.fps, rec.loop ? ", looping" : "");
  }
  text += line;
  for (std::size_t o = 0; o < rec.organs.size(); ++o) {
    if (morphs[o].motion_m < kStill_m) {  // A share of no motion is no figure: say the organ is still.
      std::snprintf(line, sizeof line, "\n  %s: %d morph targets, still (no motion to reproduce)",
                    rec.organs[o].name.c_str(), morphs[o].target_count());
      text += line;
      continue;
    }
    std::snprintf(line, sizeof line, "\n  %s: %d morph targets, error %.3g %% of the motion (RMS %.4g mm of %.4g mm)",
                  rec.organs[o].name.c_str(), morphs[o].target_count(), morphs[o].error_pct,
                  morphs[o].error_pct / 100 * morphs[o].motion_m * 1e3, morphs[o].motion_m * 1e3);
    text += line;
  }
  return text;
}

}  // namespace

FileFormat file_format(const fs::path& file) {
  const std::string ext = lower(file.extension().string());
  for (const auto& k : kKnown) {
    if (ext == k.extension) return k.format;
  }
  throw Error(ExitCode::kUsage, "cannot export to '" + file.string() + "': the extension picks the format, one of " +
                                    known_extensions());
}

std::string known_extensions() {
  std::string out;
  for (const auto& k : kKnown) out += std::string(out.empty() ? "" : ", ") + k.extension;
  return out;
}

bool needs_loop(FileFormat format, const ExportOptions& options) {
  const bool gltf = format == FileFormat::kGlb || format == FileFormat::kGltf || format == FileFormat::kHtml;
  return gltf && options.encoding == Encoding::kCompact;
}

std::vector<std::string> loop_overrides() {
  // A duration far below one cycle rounds to one loop (resolve_loop takes at least one).
  return {"output.loop=true", "output.duration=1 ms"};
}

double parse_percent(const std::string& text) {
  std::string s = text;
  while (!s.empty() && (s.back() == '%' || s.back() == ' ')) s.pop_back();
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !(v > 0 && v <= 100)) {
    throw Error(ExitCode::kUsage, "--max-error '" + text + "': give a share of the motion in (0, 100] %, e.g. 2%");
  }
  return v;
}

std::vector<MorphAnimation> morph_animations(const Recording& rec, const ExportOptions& options) {
  std::vector<MorphAnimation> morphs;
  for (const auto& organ : rec.organs) {
    morphs.push_back(options.encoding == Encoding::kCompact ? compact_morph(organ, rec, options.compact)
                                                            : frames_morph(organ, rec));
  }
  return morphs;
}

std::string export_file(const fs::path& file, const Recording& rec, const ExportOptions& options) {
  const FileFormat format = file_format(file);
  switch (format) {
    case FileFormat::kGlb:
    case FileFormat::kGltf:
    case FileFormat::kHtml: {
      const auto morphs = morph_animations(rec, options);
      if (format == FileFormat::kHtml) {
        write_html(file, gltf_bytes(rec, morphs, true), rec.scene_name, rec.camera);
      } else {
        write_gltf(file, rec, morphs, format == FileFormat::kGlb);
      }
      return "wrote " + file.string() + " (" + megabytes(file) + "): " + morph_report(rec, morphs, options);
    }
    case FileFormat::kPc2:
    case FileFormat::kMdd: {
      std::string text;
      for (const auto& f : write_point_caches(file, rec)) text += (text.empty() ? "wrote " : ", ") + f.string() + " (" + megabytes(f) + ")";
      return text + ": " + std::to_string(rec.frame_count()) + " frames, exact to float32";
    }
    case FileFormat::kPvd: {
      const fs::path folder = write_pvd(file, rec);
      return "wrote " + file.string() + " and " + std::to_string(rec.frame_count()) + " frames in " + folder.string() +
             "/: region, strain, activation, displacement per vertex";
    }
    case FileFormat::kUsda:
      write_usda(file, rec);
      return "wrote " + file.string() + " (" + megabytes(file) + "): " + std::to_string(rec.frame_count()) +
             " time samples of the points";
  }
  throw Error(ExitCode::kInternal, "unhandled export format");
}

}  // namespace systole::exporter
