#pragma once
// `systole export`: which format a file gets (by its extension), which recording it needs,
// and writing it with a one-line report of what it holds and how far it is from the
// simulation.
//
// Inputs:  an output path, a Recording (export/recording.h), options.
// Outputs: the file(s), each written atomically; the report line.
// See also: cli/export_command.cpp, docs/export.md.

#include <filesystem>
#include <string>
#include <vector>

#include "export/morph.h"
#include "export/recording.h"

namespace systole::exporter {

enum class FileFormat { kGlb, kGltf, kPc2, kMdd, kPvd, kUsda, kHtml };

/// The format of `file` by its extension; Error(kUsage) listing the known ones otherwise.
FileFormat file_format(const std::filesystem::path& file);

/// The extensions export writes, for help texts: ".glb, .gltf, ...".
std::string known_extensions();

struct ExportOptions {
  Encoding encoding = Encoding::kCompact;  ///< glTF and the web page only.
  CompactOptions compact;
};

/// Whether `format` is written from the compact loop (whole cycles after settling) rather
/// than from the clip as the scene gives it.
bool needs_loop(FileFormat format, const ExportOptions& options);

/// The -D overrides that make a scene's clip its shortest loop, as output.loop chooses it:
/// whole cycles of every drive, after settle_cycles. Loading with them refuses what cannot
/// repeat (irregular rhythms, ramps, one-off pokes) with the reason.
std::vector<std::string> loop_overrides();

/// Parses "2%", "2 %" or "2" (percent of the motion); Error(kUsage) unless in (0, 100].
double parse_percent(const std::string& text);

/// The morph animation of every organ in the chosen encoding.
std::vector<MorphAnimation> morph_animations(const Recording& rec, const ExportOptions& options);

/// Writes `file` in its format; returns a report: the files, their size, and for glTF each
/// organ's morph targets and error as RMS share of the motion.
std::string export_file(const std::filesystem::path& file, const Recording& rec, const ExportOptions& options);

}  // namespace systole::exporter
