#include "export/html.h"

#include <cmath>
#include <cstdio>

#include "common/atomic_output.h"
#include "common/base64.h"
#include "common/error.h"
#include "export/viewer_assets.h"
#include "render/camera_matrices.h"
#include "common/xml.h"

namespace systole::exporter {
namespace {

/// The viewer: load the inlined GLB, look at it from the scene's camera, play its first
/// animation in a loop.
constexpr const char* kViewer = R"JS(
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x0f1217);
scene.add(new THREE.HemisphereLight(0xffffff, 0x40342f, 1.2));
const key = new THREE.DirectionalLight(0xffffff, 2.0);
key.position.set(0.5, 1, 1);
scene.add(key);
// The scene's camera, as Systole's video sees the first frame (export/html.h).
const sceneCamera = JSON.parse(document.getElementById('camera').textContent);
const camera = new THREE.PerspectiveCamera(sceneCamera.fov_deg, 1, 0.001, 100);
let controls = null;
let organs = null;  // The organs' bounding sphere: the depth range is fitted to it.
const clock = new THREE.Clock();
let mixer = null, action = null, playing = true, duration = 0, framedBy = 'scene';

const ui = {
  play: document.getElementById('play'),
  speed: document.getElementById('speed'),
  speedText: document.getElementById('speed-text'),
  time: document.getElementById('time'),
};

// Place the camera; the controls orbit about its target and its up (OrbitControls reads
// camera.up when made, so they are made again).
function setCamera(c) {
  camera.fov = c.fov_deg;
  camera.up.fromArray(c.up);
  camera.position.fromArray(c.position);
  if (controls) controls.dispose();
  controls = new OrbitControls(camera, canvas);
  controls.target.fromArray(c.target);
  camera.lookAt(controls.target);
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
}

function currentCamera() {
  return { position: camera.position.toArray(), target: controls.target.toArray(), up: camera.up.toArray(),
           fov_deg: camera.fov };
}

// Near and far planes around the organs from wherever the camera is (as Systole fits its
// depth range), so a far camera or a zoom never clips them.
function fitDepth() {
  if (!organs) return;
  const forward = camera.getWorldDirection(new THREE.Vector3());
  const depth = forward.dot(organs.center.clone().sub(camera.position));
  const radius = organs.radius * 1.1 + 1e-6;
  const far = depth + radius;
  if (!(far > 0)) return;
  camera.far = far;
  camera.near = Math.max(depth - radius, far * 1e-3);
  camera.updateProjectionMatrix();
}

// Whether the camera shows the organs' sphere usefully: in front of it, overlapping the
// view, and across at least 5 % of its height (a far camera's few-pixel dot is no view).
function seesOrgans() {
  camera.updateMatrixWorld();
  const eye = organs.center.clone().applyMatrix4(camera.matrixWorldInverse);
  if (eye.z >= -organs.radius) return eye.z < 0 || eye.length() < organs.radius;
  const scale = 1 / (-eye.z * Math.tan(THREE.MathUtils.degToRad(camera.fov / 2)));
  const x = eye.x * scale / camera.aspect, y = eye.y * scale;
  const r = organs.radius * scale;
  return Math.abs(x) - r / camera.aspect < 1 && Math.abs(y) - r < 1 && r > 0.05;
}

function resize() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / Math.max(1, h);
  camera.updateProjectionMatrix();
}

function frame() {
  const dt = clock.getDelta();
  if (mixer && playing) mixer.update(dt);
  controls.update();
  fitDepth();
  if (action) ui.time.textContent = (action.time).toFixed(2) + ' / ' + duration.toFixed(2) + ' s';
  renderer.render(scene, camera);
}

function setPlaying(p) {
  playing = p;
  ui.play.textContent = p ? 'Pause' : 'Play';
}

ui.play.addEventListener('click', () => setPlaying(!playing));
ui.speed.addEventListener('input', () => {
  const s = Number(ui.speed.value);
  if (mixer) mixer.timeScale = s;
  ui.speedText.textContent = s.toFixed(2) + '\u00d7';
});
window.addEventListener('resize', resize);

setCamera(sceneCamera);
const bytes = Uint8Array.from(atob(document.getElementById('model').textContent.trim()), (c) => c.charCodeAt(0));
new GLTFLoader().parse(bytes.buffer, '', (gltf) => {
  scene.add(gltf.scene);
  const box = new THREE.Box3().setFromObject(gltf.scene);
  organs = box.getBoundingSphere(new THREE.Sphere());
  resize();
  if (!seesOrgans()) {
    // The scene's camera sees no organ: frame them from +z (where a scene's automatic camera
    // looks from). The box's sphere is loose around a rounded organ: 0.75 of it fills the
    // view without clipping.
    const distance = 0.75 * organs.radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
    setCamera({ position: organs.center.clone().add(new THREE.Vector3(0, 0, distance)).toArray(),
                target: organs.center.toArray(), up: [0, 1, 0], fov_deg: camera.fov });
    framedBy = 'page';
    console.info('the scene\'s camera does not show the organs (behind, outside or too far): the page frames them itself');
  }
  if (gltf.animations.length > 0) {
    mixer = new THREE.AnimationMixer(gltf.scene);
    action = mixer.clipAction(gltf.animations[0]);
    action.setLoop(THREE.LoopRepeat, Infinity);
    action.play();
    duration = gltf.animations[0].duration;
  }
  renderer.setAnimationLoop(frame);
  window.systole = {
    ready: true,
    duration_s: duration,
    framed_by: framedBy,
    scene_camera: sceneCamera,
    pause() { setPlaying(false); },
    play() { setPlaying(true); },
    seek(t_s) { if (mixer) mixer.setTime(t_s); frame(); },
    camera: currentCamera,
    set_camera(c) { setCamera(c); frame(); },
  };
}, (error) => {
  document.getElementById('error').textContent = 'Cannot read the model: ' + error;
  window.systole = { ready: false, error: String(error) };
});
)JS";

constexpr const char* kStyle = R"CSS(
html, body { margin: 0; height: 100%; background: #0f1217; color: #dde3ea; font: 14px system-ui, sans-serif; }
#view { display: block; width: 100%; height: calc(100% - 44px); }
#bar { height: 44px; display: flex; gap: 12px; align-items: center; padding: 0 12px; box-sizing: border-box; }
#bar button { min-width: 64px; }
#title { margin-left: auto; opacity: 0.7; }
#error { color: #f88; }
)CSS";

/// A `data:` URL for a JavaScript module.
std::string module_url(const std::string& text) { return "data:text/javascript;base64," + base64(text); }

/// The GLTFLoader with its one relative import made a bare name the import map resolves: a
/// `data:` module has no base URL to resolve '../utils/' against.
std::string loader_for_import_map() {
  std::string text = embedded_script("GLTFLoader.js");
  const std::string relative = "from '../utils/BufferGeometryUtils.js'";
  const auto at = text.find(relative);
  if (at == std::string::npos) {
    throw Error(ExitCode::kInternal, "the embedded GLTFLoader.js does not import ../utils/BufferGeometryUtils.js as expected");
  }
  text.replace(at, relative.size(), "from 'three/addons/utils/BufferGeometryUtils.js'");
  return text;
}

}  // namespace

const std::string& embedded_script(const std::string& name) {
  for (const auto& s : embedded_scripts()) {
    if (s.name == name) return s.text;
  }
  throw Error(ExitCode::kInternal, "the viewer script '" + name + "' was not embedded at build time");
}

std::string camera_json(const scene::Camera& camera) {
  // Row 1 of the view matrix is the up the renderer uses (render::look_at).
  const Eigen::Vector3d up = render::look_at(camera).block<1, 3>(1, 0).transpose();
  const auto triple = [](const Eigen::Vector3d& v) {
    char text[96];
    std::snprintf(text, sizeof text, "[%.9g, %.9g, %.9g]", v.x(), v.y(), v.z());
    return std::string(text);
  };
  char fov[32];
  std::snprintf(fov, sizeof fov, "%.9g", camera.fov_rad * 180 / M_PI);
  return "{\"position\": " + triple(camera.position_m) + ", \"target\": " + triple(camera.target_m) +
         ", \"up\": " + triple(up) + ", \"fov_deg\": " + fov + "}";
}

std::string html_page(const std::string& glb, const std::string& title, const scene::Camera& camera) {
  std::string page;
  page += "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<meta name=\"generator\" content=\"Systole " SYSTOLE_VERSION "\">\n";
  page += "<title>" + xml_text(title) + "</title>\n<style>" + std::string(kStyle) + "</style>\n";
  page += "<!-- three.js r160 (MIT licence, three.js authors): third_party/three/ in Systole's sources -->\n";
  page += "<script type=\"importmap\">\n{\"imports\": {\n";
  page += "  \"three\": \"" + module_url(embedded_script("three.module.min.js")) + "\",\n";
  page += "  \"three/addons/utils/BufferGeometryUtils.js\": \"" + module_url(embedded_script("BufferGeometryUtils.js")) + "\",\n";
  page += "  \"three/addons/loaders/GLTFLoader.js\": \"" + module_url(loader_for_import_map()) + "\",\n";
  page += "  \"three/addons/controls/OrbitControls.js\": \"" + module_url(embedded_script("OrbitControls.js")) + "\"\n";
  page += "}}\n</script>\n</head>\n<body>\n<canvas id=\"view\"></canvas>\n";
  page += "<div id=\"bar\"><button id=\"play\">Pause</button>\n";
  page += "<label>speed <input id=\"speed\" type=\"range\" min=\"0.1\" max=\"2\" step=\"0.05\" value=\"1\"></label>";
  page += "<span id=\"speed-text\">1.00&times;</span><span id=\"time\"></span><span id=\"error\"></span>";
  page += "<span id=\"title\">" + xml_text(title) + " &middot; drag to orbit, scroll to zoom</span></div>\n";
  page += "<script id=\"camera\" type=\"application/json\">" + camera_json(camera) + "</script>\n";
  page += "<script id=\"model\" type=\"application/octet-stream\">\n" + base64(glb) + "\n</script>\n";
  page += "<script type=\"module\">" + std::string(kViewer) + "</script>\n</body>\n</html>\n";
  return page;
}

void write_html(const std::filesystem::path& file, const std::string& glb, const std::string& title,
                const scene::Camera& camera) {
  write_file_atomically(file, html_page(glb, title, camera));
}

}  // namespace systole::exporter
