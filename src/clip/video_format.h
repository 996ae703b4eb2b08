#pragma once
// Which video a clip becomes: its format (from -o's extension, else the scene's) and the
// encoder settings the scene's output asks for.

#include <filesystem>

#include "encode/video_writer.h"
#include "scene/scene.h"

namespace systole::clip {

/// The default video path for a scene: the scene's output.file, else out/<name>.<ext>, the
/// extension of output.format (.mp4 unless the scene asks for another).
std::filesystem::path default_video_path(const scene::Scene& scene);

/// The format a video is written in: the one its extension names (.mp4, .mkv, .webm, .gif),
/// or with no extension the scene's output.format. So `-o clip.gif` makes a GIF whatever
/// the scene says; any other extension (`-o notes.txt`) is Error(kUsage).
encode::VideoFormat video_format(const scene::Scene& scene, const std::filesystem::path& video);

/// The encoder settings for the scene's output in `format`. VP9's constant quality and
/// speed follow output.quality like x264's CRF and preset (docs/teaching-visuals.md).
encode::VideoSettings video_settings(const scene::Output& out, encode::VideoFormat format);

}  // namespace systole::clip
