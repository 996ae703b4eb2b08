#pragma once
// A single self-contained web page that plays the animation: the GLB (export/gltf.h)
// inlined as base64, three.js and its loader inlined as `data:` modules behind an import
// map, and a small viewer (play/pause, speed, orbit with the mouse). Opens from disk with
// no network and no server, in any browser with WebGL.
//
// The page exposes `window.systole` (ready, duration_s, pause(), play(), seek(t_s)) so a
// headless browser can check that it plays (scripts/check-exports).
//
// Inputs:  the GLB's bytes and a title. Outputs: the page, written atomically.
// See also: third_party/three/README.md, docs/export.md.

#include <filesystem>
#include <string>

namespace systole::exporter {

std::string html_page(const std::string& glb_bytes, const std::string& title);

void write_html(const std::filesystem::path& file, const std::string& glb_bytes, const std::string& title);

}  // namespace systole::exporter
