// The live page: takes frames and state from tide serve's WebSocket /live, draws them, and sends
// the controls' and the pointer's commands (docs/serve.md).

import { decodeFrame } from "./frame.js";
import { createCanvasRenderer } from "./renderer_canvas.js";
import { createWebGLRenderer } from "./renderer_webgl.js";
import { colourAt, fitView, OBSTACLE_COLOUR, WALL_COLOUR } from "./view.js";

const canvas = document.getElementById("view");
const $ = (id) => document.getElementById(id);
const wanted = new URLSearchParams(location.search).get("renderer");
const renderer = (wanted !== "canvas" && createWebGLRenderer(canvas)) || createCanvasRenderer(canvas);

// What the page knows, for the reader and for the browser test.
const live = { renderer: renderer.kind, framesDrawn: 0, frame: null, state: null, replies: [], open: false };
window.tideLive = live;

function solid(count, rgb) {
  const colours = new Float32Array(3 * count);
  for (let i = 0; i < count; ++i) colours.set(rgb, 3 * i);
  return colours;
}

function layersOf(frame) {
  const rgb = new Float32Array(3 * frame.fluidCount);
  const span = frame.colourHigh - frame.colourLow || 1;
  for (let i = 0; i < frame.fluidCount; ++i) rgb.set(colourAt((frame.values[i] - frame.colourLow) / span), 3 * i);
  return [
    { xy: frame.walls, rgb: solid(frame.wallCount, WALL_COLOUR) },
    { xy: frame.fluid, rgb },
    { xy: frame.obstacle, rgb: solid(frame.obstacleCount, OBSTACLE_COLOUR) },
  ];
}

// Frames arrive as fast as the server publishes them; the newest is drawn once per display frame.
let pending = null;
function draw() {
  if (pending) {
    renderer.draw(pending, layersOf(pending));
    live.frame = pending;
    live.framesDrawn += 1;
    pending = null;
  }
  requestAnimationFrame(draw);
}
requestAnimationFrame(draw);

let socket = null;
function send(command) {
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(command));
}

function connect() {
  socket = new WebSocket(`ws://${location.host}/live`);
  socket.binaryType = "arraybuffer";
  socket.onopen = () => { live.open = true; };
  socket.onmessage = (event) => {
    if (typeof event.data !== "string") {
      pending = decodeFrame(event.data);
      return;
    }
    const message = JSON.parse(event.data);
    if (message.type === "reply") {
      live.replies.push(message);
      if (!message.ok || message.message) $("notice").textContent = `${message.command}: ${message.message}`;
    } else {
      if (live.state && message.notices !== live.state.notices) $("notice").textContent = message.notice;
      live.state = message;
      showSettings(message);
    }
  };
  socket.onclose = () => {
    live.open = false;
    $("readout").textContent = "disconnected: reconnecting…";
    setTimeout(connect, 1000);
  };
}
connect();

// Frames drawn per second, over the last second.
let drawnBefore = 0;
setInterval(() => {
  const fps = live.framesDrawn - drawnBefore;
  drawnBefore = live.framesDrawn;
  const s = live.state;
  if (!s) return;
  $("readout").textContent =
    `${fps} frames/s (${renderer.kind})\n` +
    `${s.sim_seconds_per_second.toFixed(2)} sim-s per s\n` +
    `${Math.round(s.steps_per_second)} steps/s\n` +
    `${s.particles} particles, ${s.scheme.toUpperCase()}\n` +
    `t = ${s.time.toFixed(2)} s${s.paused ? ", paused" : ""}`;
}, 1000);

// The controls follow the server's settings, except the one being moved.
function showSettings(s) {
  const set = (id, value) => { if (document.activeElement !== $(id)) $(id).value = value; };
  set("viscosity", Math.log10(s.viscosity));
  set("gravity", s.gravity);
  set("tilt", s.tilt);
  set("scheme", s.scheme);
  set("colour", s.colour);
  if (document.activeElement !== $("particles")) $("particles").value = s.particles;
  $("surface-tension").checked = s.surface_tension;
  $("pause").textContent = s.paused ? "Run" : "Pause";
  $("viscosity-value").textContent = `${s.viscosity.toExponential(1)} m²/s`;
  $("gravity-value").textContent = `${s.gravity.toFixed(1)} m/s²`;
  $("tilt-value").textContent = `${Math.round(s.tilt)}°`;
  $("particles-value").textContent = `${s.particles}`;
}

const gravityCommand = () => ({ command: "gravity", magnitude: Number($("gravity").value), tilt: Number($("tilt").value) });
$("viscosity").addEventListener("input", () => send({ command: "viscosity", value: 10 ** Number($("viscosity").value) }));
$("gravity").addEventListener("input", () => send(gravityCommand()));
$("tilt").addEventListener("input", () => send(gravityCommand()));
$("particles").addEventListener("change", () => send({ command: "particles", value: Number($("particles").value) }));
$("scheme").addEventListener("change", () => send({ command: "scheme", value: $("scheme").value }));
$("colour").addEventListener("change", () => send({ command: "colour", value: $("colour").value }));
$("surface-tension").addEventListener("change", () => send({ command: "surface_tension", value: $("surface-tension").checked }));
$("pause").addEventListener("click", () => send({ command: "pause", value: !(live.state && live.state.paused) }));
$("step").addEventListener("click", () => send({ command: "step" }));
$("reset").addEventListener("click", () => send({ command: "reset" }));

// The pointer drags the obstacle: pressed anywhere on the canvas, the obstacle heads for it.
let dragging = false;
let target = null;
function pointerTarget(event) {
  if (!live.frame) return null;
  const rect = canvas.getBoundingClientRect();
  const px = ((event.clientX - rect.left) * canvas.width) / rect.width;
  const py = ((event.clientY - rect.top) * canvas.height) / rect.height;
  return fitView(live.frame.view, canvas.width, canvas.height).toWorld(px, py);
}
canvas.addEventListener("pointerdown", (event) => {
  dragging = true;
  canvas.setPointerCapture(event.pointerId);
  target = pointerTarget(event);
});
canvas.addEventListener("pointermove", (event) => { if (dragging) target = pointerTarget(event); });
canvas.addEventListener("pointerup", () => { dragging = false; });
// At most one obstacle command per display frame.
function sendTarget() {
  if (target) send({ command: "obstacle", x: target[0], y: target[1] });
  target = null;
  requestAnimationFrame(sendTarget);
}
requestAnimationFrame(sendTarget);

live.send = send;
