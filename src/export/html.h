#pragma once
// A single self-contained web page that plays the animation: the GLB (export/gltf.h)
// inlined as base64, three.js and its loader inlined as `data:` modules behind an import
// map, and a small viewer (play/pause, speed, orbit with the mouse). Opens from disk with
// no network and no server, in any browser with WebGL.
//
// The page opens on the scene's own camera (the one the video's first frame is seen from,
// embedded as JSON in <script id="camera">), so a screenshot of it can be compared with
// Systole's frame of the same time; its canvas takes the window's aspect, and orbit and
// zoom start from there. A camera that sees no organ (behind it, or outside its view) is
// replaced by the page's own framing, so the page always shows the organ.
//
// The page exposes `window.systole` (ready, duration_s, pause(), play(), seek(t_s),
// camera(), set_camera(c)) so a headless browser can check that it plays and what it shows
// (scripts/check-exports).
//
// Inputs:  the GLB's bytes, a title and the camera. Outputs: the page, written atomically.
// See also: third_party/three/README.md, docs/export.md.

#include <filesystem>
#include <string>

#include "scene/scene.h"

namespace systole::exporter {

/// The camera as the page reads it: {"position": [x, y, z], "target": [...], "up": [...],
/// "fov_deg": vertical field of view}, metres and degrees; up is the one the renderer's
/// view matrix uses (render::look_at: made perpendicular to the view direction, or
/// replaced when parallel to it), so three.js' lookAt builds the same view.
std::string camera_json(const scene::Camera& camera);

std::string html_page(const std::string& glb_bytes, const std::string& title, const scene::Camera& camera);

void write_html(const std::filesystem::path& file, const std::string& glb_bytes, const std::string& title,
                const scene::Camera& camera);

}  // namespace systole::exporter
