#pragma once
// The tuning report: a Markdown summary (errors as written, fitted and tuned, per organ
// and region; generations, playbacks, wall time; the tuned parameters) and, per trained
// region, an SVG of its size over the measured cycle: target, untuned fit and tuned.

#include <filesystem>
#include <string>
#include <vector>

#include "train/tune.h"

namespace systole::train {

/// The report's Markdown text; it links the plots by the names write_report gives them.
std::string report_markdown(const std::string& scene_path, const std::vector<OrganTuning>& tunings);

/// Writes report.md and <organ>-<region>.svg into `dir` (created if missing), each atomically.
void write_report(const std::filesystem::path& dir, const std::string& scene_path, const std::vector<OrganTuning>& tunings);

}  // namespace systole::train
