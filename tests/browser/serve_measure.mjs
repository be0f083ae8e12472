// Measures tide serve as docs/serve.md reports it: for each particle count, simulated steps per
// second, simulated seconds per wall second and frames delivered per second while a client drags
// the obstacle to and fro through the water, unpaced (--pace 0); and the latency from an
// obstacle command to the first frame in which the fluid moves.
//
//   node --experimental-websocket tests/browser/serve_measure.mjs TIDE_BINARY [SECONDS] [COUNTS...]

import { spawn } from "node:child_process";

const [tide, secondsText = "10", ...countTexts] = process.argv.slice(2);
const seconds = Number(secondsText);
const counts = countTexts.length > 0 ? countTexts.map(Number) : [2000, 5000, 20000];
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

const server = spawn(tide, ["serve", "--port", "0", "--pace", "0", ...(process.env.THREADS ? ["--threads", process.env.THREADS] : [])],
  { stdio: ["ignore", "pipe", "ignore"] });
const url = await new Promise((resolve) => {
  let out = "";
  server.stdout.on("data", (chunk) => {
    out += chunk;
    const found = out.match(/open (http:\/\/\S+) /);
    if (found) resolve(found[1]);
  });
});
const state = async () => (await fetch(`${url}state`)).json();

const socket = new WebSocket(`${url.replace("http", "ws")}live`);
socket.binaryType = "arraybuffer";
let frames = 0;
let onFrame = null;
socket.onmessage = (event) => {
  if (typeof event.data === "string") return;
  frames += 1;
  if (onFrame) onFrame(event.data);
};
await new Promise((resolve) => (socket.onopen = resolve));
const send = (command) => socket.send(JSON.stringify(command));

// The largest colour value (speed) of a frame message.
function maxSpeed(buffer) {
  const header = new DataView(buffer, 0, 64);
  const n = header.getUint32(8, true);
  const values = new Float32Array(buffer, 64 + 8 * n, n);
  return values.reduce((a, b) => Math.max(a, b), 0);
}

console.log("| particles | steps/s | sim-s per wall-s | frames/s delivered |");
console.log("| --- | --- | --- | --- |");
for (const count of counts) {
  send({ command: "particles", value: count });
  send({ command: "obstacle", x: 0.8, y: 0.55 });
  await sleep(3000);
  const start = await state();
  const framesBefore = frames;
  const t0 = Date.now();
  // The obstacle swept to and fro through the water, 30 targets a second.
  while (Date.now() - t0 < seconds * 1000) {
    const phase = ((Date.now() - t0) / 1000) * 0.8 * Math.PI;
    send({ command: "obstacle", x: 0.8 + 0.55 * Math.sin(phase), y: 0.14 });
    await sleep(33);
  }
  const end = await state();
  const wall = (Date.now() - t0) / 1000;
  const steps = (end.steps - start.steps) / wall;
  const simulated = (end.time - start.time) / wall;
  console.log(`| ${end.particles} | ${steps.toFixed(0)} | ${simulated.toFixed(2)} | ${((frames - framesBefore) / wall).toFixed(1)} |`);
}

// Latency: the obstacle resting in still water is sent 0.3 m away; the time until the first
// frame whose fastest particle is three times as fast as before.
send({ command: "particles", value: 2000 });
send({ command: "obstacle", x: 0.5, y: 0.14 });
await sleep(4000);
const latencies = [];
for (let k = 0; k < 5; ++k) {
  let before = 0;
  onFrame = (buffer) => { before = Math.max(before, maxSpeed(buffer)); };
  await sleep(500);
  const quiet = before;
  const sent = performance.now();
  const moved = new Promise((resolve) => {
    onFrame = (buffer) => { if (maxSpeed(buffer) > 3 * quiet + 0.05) resolve(performance.now() - sent); };
  });
  send({ command: "obstacle", x: k % 2 === 0 ? 0.8 : 0.5, y: 0.14 });
  latencies.push(await moved);
  onFrame = null;
  await sleep(2500);
}
console.log(`latency from an obstacle command to a frame with the fluid moving: ${latencies.map((ms) => ms.toFixed(0)).join(", ")} ms`);
socket.close();
server.kill("SIGTERM");
