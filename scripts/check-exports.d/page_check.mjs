// The web page in headless Chromium (playwright-core, /usr/bin/chromium): it loads with no
// network, WebGL runs on a software rasterizer, and two moments of the animation differ
// where the organ moves.
//
//   node page_check.mjs PAGE.html SCREENSHOT.png [--match FRAME.png --control CONTROL.png --frame K/N]
//
// With --match, the page is also compared with Systole's own frame of the same time: the
// viewport is set so the canvas has FRAME.png's size, the page is paused at its loop's frame
// K of N (t = K / N of the loop's duration, where the compact loop's key K holds frame K), and the two silhouettes (a pixel is organ where it differs from the
// background colour both renderers share, sRGB (15, 18, 23)) must agree within
// kSilhouetteTolerance as 1 - IoU (the pixels classified differently over the union of the
// two silhouettes). Two controls show the tolerance tells a wrong view from the right one,
// and must exceed it: CONTROL.png (Systole's frame half a loop away: a wrong frame), the page
// held at t = 0 (a frozen organ) and the page turned 5 degrees about its target (a wrong camera).
// Exit 0: plays (and matches); 1: fails; 2: no software WebGL path in this Chromium (a skip, said why).
import { chromium } from 'playwright-core';
import fs from 'fs';
import path from 'path';

const args = process.argv.slice(2);
const option = (name) => { const i = args.indexOf(name); return i >= 0 ? args.splice(i, 2)[1] : undefined; };
const match = option('--match'), control = option('--control');
const [match_frame, loop_frames] = (option('--frame') ?? '0/1').split('/').map(Number);
const [page_file, screenshot] = args;
// 1 - IoU of the two silhouettes. Measured at the right time and camera: 1.28 % (heart) and
// 1.85 % (lungs): a rim of pixels where the two renderers shade and anti-alias the edge
// differently, and the compact loop's 1-2 % motion error. The controls: a frame half a loop
// away 11.6 % and 7.6 %, the page frozen at t = 0 11.2 % and 11.3 %, the camera turned 5 deg
// 3.56 % and 3.11 %. 2.5 % lies midway between the worst right figure and the weakest
// control, so each control fails it and the right view passes with 0.65 points to spare
// (docs/export.md).
const kSilhouetteTolerance = 0.025;
// A pixel differs from the background (or another pixel) when its |dR| + |dG| + |dB| exceeds this (of 765).
const kDiffers = 30;
// Software WebGL paths Debian's Chromium may offer, tried in order.
const paths = [
  ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  ['--use-gl=angle', '--use-angle=swiftshader-webgl', '--enable-unsafe-swiftshader'],
  ['--use-gl=swiftshader', '--enable-unsafe-swiftshader'],
];

async function attempt(flags) {
  const browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', ...flags],
  });
  try {
    const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
    const logs = [];
    page.on('console', (m) => logs.push(`${m.type()}: ${m.text()}`));
    page.on('pageerror', (e) => logs.push(`pageerror: ${e.message}`));
    // Any request beyond the page itself would be the network: refuse and count it.
    let requests = 0;
    await page.route('**/*', (route) => {
      if (route.request().url().startsWith('file:')) return route.continue();
      requests += 1;
      return route.abort();
    });
    await page.goto('file://' + path.resolve(page_file));
    const webgl = await page.evaluate(() => {
      const gl = document.createElement('canvas').getContext('webgl2');
      if (!gl) return null;
      const info = gl.getExtension('WEBGL_debug_renderer_info');
      return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
    });
    if (!webgl) return { webgl: null, flags };
    await page.waitForFunction(() => window.systole !== undefined, null, { timeout: 120000 });
    const state = await page.evaluate(() => ({ ready: window.systole.ready, duration: window.systole.duration_s,
                                              error: window.systole.error }));
    if (!state.ready) return { webgl, flags, error: state.error, logs };
    // Two moments of the loop, paused: the first frame and 40 % into it.
    const a = (await canvas_at(page, 0)).data;
    await page.screenshot({ path: screenshot.replace(/\.png$/, '-t0.png') });
    const b = (await canvas_at(page, state.duration * 0.4)).data;
    await page.screenshot({ path: screenshot });
    const background = [a[0], a[1], a[2]];
    let organ = 0, differ = 0;
    for (let i = 0; i < a.length; i += 4) {
      if (Math.abs(a[i] - background[0]) + Math.abs(a[i + 1] - background[1]) + Math.abs(a[i + 2] - background[2]) > 30) organ += 1;
      if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 30) differ += 1;
    }
    const result = { webgl, flags, duration: state.duration, pixels: a.length / 4, organ, differ, requests, logs };
    if (match) result.match = await compare(page, state.duration);
    return result;
  } finally {
    await browser.close();
  }
}

const differs = (p, i, q, j) =>
  Math.abs(p[i] - q[j]) + Math.abs(p[i + 1] - q[j + 1]) + Math.abs(p[i + 2] - q[j + 2]) > kDiffers;

/// A PNG's RGBA pixels, decoded by the browser (no image package needed).
async function png_pixels(page, file) {
  const b64 = fs.readFileSync(file).toString('base64');
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + b64;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.naturalWidth;
    c.height = img.naturalHeight;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    return { width: c.width, height: c.height, data: Array.from(g.getImageData(0, 0, c.width, c.height).data) };
  }, b64);
}

/// The organ pixels of an image (1: organ), after checking its background is the shared,
/// uniform one: the four corners are that colour.
function silhouette(img, name) {
  const { width: w, height: h, data } = img;
  const bg = [15, 18, 23];
  for (const [x, y] of [[0, 0], [w - 1, 0], [0, h - 1], [w - 1, h - 1]]) {
    if (differs(data, 4 * (y * w + x), bg, 0)) throw new Error(`${name}: corner (${x}, ${y}) is not the background (15, 18, 23)`);
  }
  const s = new Uint8Array(w * h);
  for (let i = 0; i < w * h; ++i) s[i] = differs(data, 4 * i, bg, 0) ? 1 : 0;
  return s;
}

/// 1 - IoU of two silhouettes, and their sizes. unit: 1
function mismatch(a, b) {
  let union = 0, both = 0, na = 0, nb = 0;
  for (let i = 0; i < a.length; ++i) {
    union += a[i] | b[i];
    both += a[i] & b[i];
    na += a[i];
    nb += b[i];
  }
  return { one_minus_iou: union ? 1 - both / union : 1, page: na, systole: nb };
}

/// The page paused at t seconds of its loop: the canvas' size, its RGBA pixels, and how it was framed.
function canvas_at(page, t) {
  return page.evaluate((t) => {
    window.systole.pause();
    window.systole.seek(t);
    const canvas = document.getElementById('view');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const g = copy.getContext('2d');
    g.drawImage(canvas, 0, 0);
    return { width: copy.width, height: copy.height, framed_by: window.systole.framed_by,
             data: Array.from(g.getImageData(0, 0, copy.width, copy.height).data) };
  }, t);
}

/// The page at loop frame match_frame on its scene camera against Systole's frame, and the two controls.
async function compare(page, state_duration) {
  const frame = await png_pixels(page, match);
  const other = await png_pixels(page, control);
  // The canvas is the window less the 44 px control bar.
  await page.setViewportSize({ width: frame.width, height: frame.height + 44 });
  const t_match = match_frame * state_duration / loop_frames;
  const shot = (t = t_match) => canvas_at(page, t);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));  // The resize has run.
  const own = await shot();
  await page.screenshot({ path: screenshot.replace(/\.png$/, '-match.png') });
  if (own.width !== frame.width || own.height !== frame.height) {
    throw new Error(`the canvas is ${own.width}x${own.height}, Systole's frame ${frame.width}x${frame.height}`);
  }
  const page_s = silhouette(own, 'page'), systole_s = silhouette(frame, match);
  const right = mismatch(page_s, systole_s);
  const wrong_time = mismatch(page_s, silhouette(other, control));
  // A wrong camera: the eye turned 5 degrees about the target, around the camera's up.
  const turned = await page.evaluate(() => {
    const c = window.systole.camera();
    const a = 5 * Math.PI / 180, u = c.up, p = c.position.map((x, i) => x - c.target[i]);
    // Rodrigues' rotation of p about the unit axis u.
    const dot = u[0] * p[0] + u[1] * p[1] + u[2] * p[2];
    const cross = [u[1] * p[2] - u[2] * p[1], u[2] * p[0] - u[0] * p[2], u[0] * p[1] - u[1] * p[0]];
    const q = p.map((x, i) => x * Math.cos(a) + cross[i] * Math.sin(a) + u[i] * dot * (1 - Math.cos(a)));
    window.systole.set_camera({ ...c, position: q.map((x, i) => x + c.target[i]) });
    return c;
  });
  const wrong_camera = mismatch(silhouette(await shot(), 'page turned 5 deg'), systole_s);
  await page.evaluate((c) => window.systole.set_camera(c), turned);
  // A frozen organ: the page held at its first frame.
  const frozen = mismatch(silhouette(await shot(0), 'page at t = 0'), systole_s);
  return { framed_by: own.framed_by, width: own.width, height: own.height, right, wrong_time, wrong_camera, frozen };
}

let last = null;
for (const flags of paths) {
  try {
    last = await attempt(flags);
  } catch (e) {
    last = { flags, error: String(e) };
  }
  if (last.webgl) break;
}
if (!last || !last.webgl) {
  console.log(`SKIP ${page_file}: no software WebGL in this Chromium (tried ${paths.map((p) => p.join(' ')).join('; ')}): ` +
              (last && last.error ? last.error : 'no WebGL2 context'));
  process.exit(2);
}
if (last.error) {
  console.log(`FAIL ${page_file}: WebGL "${last.webgl}" with ${last.flags.join(' ')}; the page did not load its model: ${last.error}`);
  for (const l of last.logs ?? []) console.log('  ' + l);
  process.exit(1);
}
// The organ covers a visible part of the frame, and a share of it changes between the moments.
let ok = last.organ > 0.02 * last.pixels && last.differ > 0.002 * last.pixels && last.requests === 0;
console.log(`${ok ? 'PASS' : 'FAIL'} ${page_file}: WebGL "${last.webgl}" (${last.flags.join(' ')}), loop ${last.duration.toFixed(3)} s, ` +
            `organ on ${(100 * last.organ / last.pixels).toFixed(1)} % of the canvas, ${(100 * last.differ / last.pixels).toFixed(2)} % ` +
            `of the canvas changes between t = 0 and 40 % of the loop, ${last.requests} network requests; screenshot ${screenshot}`);
if (match) {
  const m = last.match;
  const pct = (x) => (100 * x.one_minus_iou).toFixed(2) + ' %';
  const matches = m.framed_by === 'scene' && m.right.one_minus_iou <= kSilhouetteTolerance;
  // The controls must fail the tolerance, or it would not tell a wrong view from the right one.
  const discriminates = [m.wrong_time, m.wrong_camera, m.frozen].every((c) => c.one_minus_iou > kSilhouetteTolerance);
  console.log(`${matches ? 'PASS' : 'FAIL'} ${page_file}: at loop frame ${match_frame} of ${loop_frames} (t = ${(match_frame * last.duration / loop_frames).toFixed(4)} s) on the ${m.framed_by}'s camera, ` +
              `${m.width}x${m.height}, the page's silhouette (${m.right.page} px) and Systole's frame ${path.basename(match)} ` +
              `(${m.right.systole} px) differ on 1 - IoU = ${pct(m.right)} (tolerance ${100 * kSilhouetteTolerance} %)`);
  console.log(`${discriminates ? 'PASS' : 'FAIL'} ${page_file}: controls above the tolerance: Systole's frame half a loop away ` +
              `(${path.basename(control)}) 1 - IoU = ${pct(m.wrong_time)}, the page frozen at t = 0 ${pct(m.frozen)}, ` +
              `the page's camera turned 5 deg ${pct(m.wrong_camera)}`);
  ok = ok && matches && discriminates;
}
// SwiftShader's performance notes about reading pixels back are not the page's problems.
for (const l of last.logs) if (!l.startsWith('log:') && !l.includes('GPU stall due to ReadPixels')) console.log('  ' + l);
process.exit(ok ? 0 : 1);
