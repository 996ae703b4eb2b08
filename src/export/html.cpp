#include "export/html.h"

#include "common/error.h"
#include "export/base64.h"
#include "export/viewer_assets.h"
#include "export/write_file.h"

namespace systole::exporter {
namespace {

/// The viewer: load the inlined GLB, frame it, play its first animation in a loop.
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
const camera = new THREE.PerspectiveCamera(40, 1, 0.001, 100);
const controls = new OrbitControls(camera, canvas);
const clock = new THREE.Clock();
let mixer = null, action = null, playing = true, duration = 0;

const ui = {
  play: document.getElementById('play'),
  speed: document.getElementById('speed'),
  speedText: document.getElementById('speed-text'),
  time: document.getElementById('time'),
};

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

const bytes = Uint8Array.from(atob(document.getElementById('model').textContent.trim()), (c) => c.charCodeAt(0));
new GLTFLoader().parse(bytes.buffer, '', (gltf) => {
  scene.add(gltf.scene);
  // Frame the organs: the camera on +z (where a scene's default camera looks from).
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const sphere = box.getBoundingSphere(new THREE.Sphere());
  // The box's sphere is loose around a rounded organ: 0.75 of it fills the view without clipping.
  const distance = 0.75 * sphere.radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
  camera.position.copy(sphere.center).add(new THREE.Vector3(0, 0, distance));
  camera.near = distance / 100;
  camera.far = distance * 10;
  controls.target.copy(sphere.center);
  if (gltf.animations.length > 0) {
    mixer = new THREE.AnimationMixer(gltf.scene);
    action = mixer.clipAction(gltf.animations[0]);
    action.setLoop(THREE.LoopRepeat, Infinity);
    action.play();
    duration = gltf.animations[0].duration;
  }
  resize();
  renderer.setAnimationLoop(frame);
  window.systole = {
    ready: true,
    duration_s: duration,
    pause() { setPlaying(false); },
    play() { setPlaying(true); },
    seek(t_s) { if (mixer) mixer.setTime(t_s); frame(); },
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

std::string escape_html(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

}  // namespace

const std::string& embedded_script(const std::string& name) {
  for (const auto& s : embedded_scripts()) {
    if (s.name == name) return s.text;
  }
  throw Error(ExitCode::kInternal, "the viewer script '" + name + "' was not embedded at build time");
}

std::string html_page(const std::string& glb, const std::string& title) {
  std::string page;
  page += "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<meta name=\"generator\" content=\"Systole " SYSTOLE_VERSION "\">\n";
  page += "<title>" + escape_html(title) + "</title>\n<style>" + std::string(kStyle) + "</style>\n";
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
  page += "<span id=\"title\">" + escape_html(title) + " &middot; drag to orbit, scroll to zoom</span></div>\n";
  page += "<script id=\"model\" type=\"application/octet-stream\">\n" + base64(glb) + "\n</script>\n";
  page += "<script type=\"module\">" + std::string(kViewer) + "</script>\n</body>\n</html>\n";
  return page;
}

void write_html(const std::filesystem::path& file, const std::string& glb, const std::string& title) {
  write_file_atomically(file, html_page(glb, title));
}

}  // namespace systole::exporter
