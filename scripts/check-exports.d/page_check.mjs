// The web page in headless Chromium (playwright-core, /usr/bin/chromium): it loads with no
// network, WebGL runs on a software rasterizer, and two moments of the animation differ
// where the organ moves. node page_check.mjs PAGE.html SCREENSHOT.png
// Exit 0: plays; 1: fails; 2: no software WebGL path in this Chromium (a skip, said why).
import { chromium } from 'playwright-core';
import path from 'path';

const [page_file, screenshot] = process.argv.slice(2);
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
    const capture = (t) => page.evaluate((t) => {
      window.systole.pause();
      window.systole.seek(t);
      const canvas = document.getElementById('view');
      const copy = document.createElement('canvas');
      copy.width = canvas.width;
      copy.height = canvas.height;
      const g = copy.getContext('2d');
      g.drawImage(canvas, 0, 0);
      return Array.from(g.getImageData(0, 0, copy.width, copy.height).data);
    }, t);
    const a = await capture(0);
    await page.screenshot({ path: screenshot.replace(/\.png$/, '-t0.png') });
    const b = await capture(state.duration * 0.4);
    await page.screenshot({ path: screenshot });
    const background = [a[0], a[1], a[2]];
    let organ = 0, differ = 0;
    for (let i = 0; i < a.length; i += 4) {
      if (Math.abs(a[i] - background[0]) + Math.abs(a[i + 1] - background[1]) + Math.abs(a[i + 2] - background[2]) > 30) organ += 1;
      if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 30) differ += 1;
    }
    return { webgl, flags, duration: state.duration, pixels: a.length / 4, organ, differ, requests, logs };
  } finally {
    await browser.close();
  }
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
const ok = last.organ > 0.02 * last.pixels && last.differ > 0.002 * last.pixels && last.requests === 0;
console.log(`${ok ? 'PASS' : 'FAIL'} ${page_file}: WebGL "${last.webgl}" (${last.flags.join(' ')}), loop ${last.duration.toFixed(3)} s, ` +
            `organ on ${(100 * last.organ / last.pixels).toFixed(1)} % of the canvas, ${(100 * last.differ / last.pixels).toFixed(2)} % ` +
            `of the canvas changes between t = 0 and 40 % of the loop, ${last.requests} network requests; screenshot ${screenshot}`);
// SwiftShader's performance notes about reading pixels back are not the page's problems.
for (const l of last.logs) if (!l.startsWith('log:') && !l.includes('GPU stall due to ReadPixels')) console.log('  ' + l);
process.exit(ok ? 0 : 1);
