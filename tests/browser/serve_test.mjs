// End-to-end test of `tide serve` in headless Chromium (docs/serve.md, "Tests"): starts the
// server on a free port, loads the page, and checks through the page's canvas and the server's
// /state that particles are drawn, that dragging the obstacle moves the fluid, that tilting
// gravity moves it, and that malformed commands are refused while the server keeps serving.
// Saves screenshots. Exits 77 (skipped, with the reason) where Chromium or playwright-core is
// missing.
//
//   node tests/browser/serve_test.mjs TIDE_BINARY OUTPUT_DIR

import { spawn } from "node:child_process";
import { existsSync, mkdirSync } from "node:fs";
import http from "node:http";
import path from "node:path";

const SKIP = 77;
const chromiumPath = process.env.CHROMIUM ?? "/usr/bin/chromium";
const [tideBinary, outputDir = "serve-browser-test"] = process.argv.slice(2);

function skip(reason) {
  console.log(`serve_test: SKIPPED: ${reason}`);
  process.exit(SKIP);
}

if (!tideBinary) {
  console.error("usage: node serve_test.mjs TIDE_BINARY [OUTPUT_DIR]");
  process.exit(2);
}
if (!existsSync(chromiumPath)) skip(`no Chromium at ${chromiumPath} (apt-get install chromium; CHROMIUM=path)`);
let chromium;
try {
  ({ chromium } = await import("playwright-core"));
} catch {
  skip("playwright-core is not installed (npm ci at the repository root)");
}

const failures = [];
function check(condition, what) {
  console.log(`${condition ? "ok  " : "FAIL"} ${what}`);
  if (!condition) failures.push(what);
}
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

function get(port, rawPath) {
  return new Promise((resolve, reject) => {
    const request = http.request({ host: "127.0.0.1", port, path: rawPath, method: "GET" }, (response) => {
      let body = "";
      response.on("data", (chunk) => (body += chunk));
      response.on("end", () => resolve({ status: response.statusCode, body }));
    });
    request.on("error", reject);
    request.end();
  });
}
const state = async (port) => JSON.parse((await get(port, "/state")).body);

// Waits for `condition(state)` for up to `ms`; the last state read.
async function waitForState(port, ms, condition) {
  const end = Date.now() + ms;
  let last = await state(port);
  while (!condition(last) && Date.now() < end) {
    await sleep(100);
    last = await state(port);
  }
  return last;
}

// The server, on a free port, with the URL it prints.
const server = spawn(tideBinary, ["serve", "--port", "0", "--threads", "2"], { stdio: ["ignore", "pipe", "inherit"] });
const url = await new Promise((resolve, reject) => {
  let out = "";
  const timer = setTimeout(() => reject(new Error(`tide serve printed no URL in 60 s: ${out}`)), 60000);
  server.stdout.on("data", (chunk) => {
    out += chunk;
    const found = out.match(/open (http:\/\/\S+) /);
    if (found) {
      clearTimeout(timer);
      resolve(found[1]);
    }
  });
  server.on("exit", (code) => reject(new Error(`tide serve exited with ${code}: ${out}`)));
});
const port = Number(new URL(url).port);
console.log(`serve_test: ${url}`);

mkdirSync(outputDir, { recursive: true });
const browser = await chromium.launch({
  executablePath: chromiumPath,
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync"],
});
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 640 } });
  page.on("pageerror", (error) => check(false, `no error in the page: ${error.message}`));
  await page.goto(url);
  await page.waitForFunction(() => window.tideLive && window.tideLive.framesDrawn > 10 && window.tideLive.state, null, { timeout: 30000 });

  // Particles drawn: pixels of the canvas that are not its background, and fluid-blue ones.
  const countPixels = () => page.evaluate(() => {
    const view = document.getElementById("view");
    const copy = document.createElement("canvas");
    copy.width = view.width;
    copy.height = view.height;
    const context = copy.getContext("2d");
    context.drawImage(view, 0, 0);
    const data = context.getImageData(0, 0, copy.width, copy.height).data;
    let drawn = 0, blue = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      if (Math.abs(r - 11) + Math.abs(g - 15) + Math.abs(b - 20) > 30) drawn += 1;
      if (b > 120 && b > r + 40) blue += 1;
    }
    return { drawn, blue, renderer: window.tideLive.renderer };
  });
  const pixels = await countPixels();
  console.log(`serve_test: renderer ${pixels.renderer}, ${pixels.drawn} pixels drawn, ${pixels.blue} of them fluid-blue`);
  check(pixels.drawn > 20000 && pixels.blue > 10000, "the canvas shows the particles (pixels drawn, fluid-blue ones)");

  // The obstacle dragged from above the water through it: the fluid speeds up.
  const settled = await state(port);
  const box = await page.locator("#view").boundingBox();
  const frame = await page.evaluate(() => window.tideLive.frame);
  const toPage = (x, y) => {
    const [x0, y0, x1, y1] = frame.view;
    const scale = Math.min(960 / (x1 - x0), 540 / (y1 - y0));
    const left = (960 - scale * (x1 - x0)) / 2, bottom = (540 - scale * (y1 - y0)) / 2;
    const k = box.width / 960;
    return [box.x + k * (left + (x - x0) * scale), box.y + k * (540 - bottom - (y - y0) * scale)];
  };
  // Down into the water (to half its depth, twice the fluid's mean height) and along it.
  const width = frame.view[2] - frame.view[0], under = settled.mean_y;
  await page.mouse.move(...toPage(settled.obstacle_x, settled.obstacle_y));
  await page.mouse.down();
  for (let k = 0; k <= 30; ++k) {
    const s = k / 30;
    await page.mouse.move(...toPage(settled.obstacle_x - 0.25 * width * s, settled.obstacle_y + (under - settled.obstacle_y) * s));
    await sleep(33);
  }
  for (let k = 0; k <= 30; ++k) {
    await page.mouse.move(...toPage(settled.obstacle_x - 0.25 * width + 0.45 * width * (k / 30), under));
    await sleep(33);
  }
  const dragged = await waitForState(port, 20000, (s) => s.obstacle_y < 2 * settled.mean_y &&
    Math.abs(s.obstacle_x - settled.obstacle_x) > 0.2 && s.mean_speed > 4 * settled.mean_speed && s.mean_speed > 0.05);
  await page.mouse.up();
  console.log(`serve_test: obstacle (${settled.obstacle_x.toFixed(3)}, ${settled.obstacle_y.toFixed(3)}) -> ` +
    `(${dragged.obstacle_x.toFixed(3)}, ${dragged.obstacle_y.toFixed(3)}); mean fluid speed ` +
    `${settled.mean_speed.toFixed(4)} -> ${dragged.mean_speed.toFixed(4)} m/s`);
  check(dragged.obstacle_y < 2 * settled.mean_y && Math.abs(dragged.obstacle_x - settled.obstacle_x) > 0.2,
    "the drag moved the obstacle into the water");
  check(dragged.mean_speed > 4 * settled.mean_speed && dragged.mean_speed > 0.05, "the dragged obstacle set the fluid moving");
  await page.screenshot({ path: path.join(outputDir, "serve_drag.png") });

  // Gravity tilted 40 degrees towards +x through the page's slider: the water runs that way.
  const level = await state(port);
  await page.evaluate(() => {
    const tilt = document.getElementById("tilt");
    tilt.value = "40";
    tilt.dispatchEvent(new Event("input"));
  });
  const tilted = await waitForState(port, 20000, (s) => s.mean_x > level.mean_x + 0.1);
  console.log(`serve_test: tilt ${tilted.tilt}: mean fluid x ${level.mean_x.toFixed(3)} -> ${tilted.mean_x.toFixed(3)} m`);
  check(tilted.tilt === 40 && tilted.mean_x > level.mean_x + 0.1, "tilting gravity sends the water to the low side");
  await page.screenshot({ path: path.join(outputDir, "serve_tilt.png") });

  // Malformed commands on a second connection: refusals, clamping, and garbage that closes it.
  const answers = await page.evaluate(async () => {
    const open = () => new Promise((resolve, reject) => {
      const socket = new WebSocket(`ws://${location.host}/live`);
      const replies = [];
      socket.onmessage = (event) => {
        if (typeof event.data === "string" && event.data.includes('"reply"')) replies.push(JSON.parse(event.data));
      };
      socket.onopen = () => resolve({ socket, replies });
      socket.onerror = () => reject(new Error("no connection"));
    });
    const closed = (socket) => new Promise((resolve) => {
      if (socket.readyState === WebSocket.CLOSED) resolve(true);
      socket.addEventListener("close", () => resolve(true));
      setTimeout(() => resolve(false), 3000);
    });
    const pause = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
    const first = await open();
    for (const text of ['{"command":"warp"}', '{"command":"viscosity","value":"thick"}', '{"command":"gravity"}',
      '{"command":"gravity","magnitude":1e9,"tilt":40}', '[1,2]', '{"command":"particles","value":2.5}'])
      first.socket.send(text);
    await pause(500);
    const repliesBefore = first.replies.slice();
    first.socket.send("this is not JSON");
    const closedByGarbage = await closed(first.socket);
    const second = await open();
    second.socket.send("x".repeat(10000));
    const closedByOversize = await closed(second.socket);
    const third = await open();
    third.socket.send(new Uint8Array([1, 2, 3]));
    const closedByBinary = await closed(third.socket);
    return { replies: repliesBefore, closedByGarbage, closedByOversize, closedByBinary };
  });
  const [warp, thick, missing, huge, array, fraction] = answers.replies;
  for (const r of answers.replies) console.log(`serve_test: reply ${JSON.stringify(r)}`);
  check(answers.replies.length === 6, "every malformed command got a reply");
  check(warp && !warp.ok && /unknown command/.test(warp.message), "an unknown command is refused");
  check(thick && !thick.ok && /must be a number/.test(thick.message), "a value of the wrong type is refused");
  check(missing && !missing.ok && /missing field/.test(missing.message), "a missing field is refused");
  check(huge && huge.ok && /clamped to 20/.test(huge.message), "an out-of-range gravity is clamped to its limit");
  check(array && !array.ok, "a JSON value that is not an object is refused");
  check(fraction && !fraction.ok && /integer/.test(fraction.message), "a fractional particle count is refused");
  check(answers.closedByGarbage && answers.closedByOversize && answers.closedByBinary,
    "garbage, an oversized message and a binary message each close their connection");
  const drawnBefore = await page.evaluate(() => window.tideLive.framesDrawn);
  await sleep(1000);
  const after = await page.evaluate(() => ({ drawn: window.tideLive.framesDrawn, open: window.tideLive.open }));
  const clamped = await state(port);
  check(after.open && after.drawn > drawnBefore + 10, "the page's own connection kept drawing frames");
  check(clamped.gravity === 20, "the clamped gravity took effect (20 m/s²)");

  // Static files: nothing outside the web folder.
  for (const raw of ["/../../../../etc/passwd", "/%2e%2e/%2e%2e/%2e%2e/etc/passwd", "/..%2f..%2fetc%2fpasswd", "/%2e%2e/CMakeLists.txt", "/scenes/../../CMakeLists.txt"]) {
    const answer = await get(port, raw);
    check(answer.status === 404 && !answer.body.includes("root:"), `GET ${raw} is refused (${answer.status})`);
  }
  check((await get(port, "/")).status === 200, "the page is still served");

  // Every other control of the page, through its own elements.
  const setControl = (id, value, event) => page.evaluate(([id, value, event]) => {
    const element = document.getElementById(id);
    if (element.type === "checkbox") element.checked = value; else element.value = value;
    element.dispatchEvent(new Event(event));
  }, [id, value, event]);
  await setControl("colour", "pressure", "change");
  check((await waitForState(port, 10000, (s) => s.colour === "pressure")).colour === "pressure", "the colour menu colours by pressure");
  await setControl("viscosity", "-2.5", "input");
  check(Math.abs((await waitForState(port, 10000, (s) => Math.abs(s.viscosity - 10 ** -2.5) < 1e-9)).viscosity - 10 ** -2.5) < 1e-9,
    "the viscosity slider sets the viscosity");
  await page.click("#pause");
  const paused = await waitForState(port, 10000, (s) => s.paused);
  await page.click("#step");
  const stepped = await waitForState(port, 10000, (s) => s.steps === paused.steps + 1);
  check(paused.paused && stepped.steps === paused.steps + 1, "Pause stops the steps and Step takes one");
  await page.click("#pause");
  check(!(await waitForState(port, 10000, (s) => !s.paused)).paused, "Run resumes");
  const before = await state(port);
  await page.click("#reset");
  check((await waitForState(port, 10000, (s) => s.time < before.time)).time < before.time, "Reset starts again");
  await setControl("particles", "4000", "change");
  const refilled = await waitForState(port, 20000, (s) => Math.abs(s.particles - 4000) < 400);
  check(Math.abs(refilled.particles - 4000) < 400, `the particle slider refills the tank (${refilled.particles} particles)`);
  await setControl("scheme", "wcsph", "change");
  await waitForState(port, 20000, (s) => s.scheme === "wcsph");
  await setControl("surface-tension", true, "change");
  const cohesive = await waitForState(port, 20000, (s) => s.scheme === "wcsph" && s.surface_tension);
  check(cohesive.scheme === "wcsph" && cohesive.surface_tension, "the scheme menu and the surface-tension switch take effect");

  // The 2D-canvas fallback draws too.
  const fallback = await browser.newPage({ viewport: { width: 1280, height: 640 } });
  await fallback.goto(`${url}?renderer=canvas`);
  await fallback.waitForFunction(() => window.tideLive && window.tideLive.framesDrawn > 5, null, { timeout: 30000 });
  const fallbackPixels = await fallback.evaluate(() => {
    const view = document.getElementById("view");
    const data = view.getContext("2d").getImageData(0, 0, view.width, view.height).data;
    let drawn = 0;
    for (let i = 0; i < data.length; i += 4) if (Math.abs(data[i] - 11) + Math.abs(data[i + 1] - 15) + Math.abs(data[i + 2] - 20) > 30) drawn += 1;
    return { drawn, renderer: window.tideLive.renderer };
  });
  check(fallbackPixels.renderer === "canvas2d" && fallbackPixels.drawn > 20000, `the 2D-canvas fallback draws the particles (${fallbackPixels.drawn} pixels)`);
  await fallback.screenshot({ path: path.join(outputDir, "serve_canvas2d.png") });
} finally {
  await browser.close();
  server.kill("SIGTERM");
}
const code = await new Promise((resolve) => server.on("exit", (c) => resolve(c)));
check(code === 0, `tide serve stopped cleanly on SIGTERM (exit code ${code})`);
console.log(`serve_test: screenshots in ${outputDir}`);
if (failures.length > 0) {
  console.log(`serve_test: ${failures.length} check(s) failed`);
  process.exit(1);
}
console.log("serve_test: all checks passed");
