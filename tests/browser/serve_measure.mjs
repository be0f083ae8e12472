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

// A tide serve with a client on its WebSocket: `pace` as --pace.
async function startServer(pace) {
  const server = spawn(tide, ["serve", "--port", "0", "--pace", String(pace),
    ...(process.env.THREADS ? ["--threads", process.env.THREADS] : [])], { stdio: ["ignore", "pipe", "ignore"] });
  const url = await new Promise((resolve) => {
    let out = "";
    server.stdout.on("data", (chunk) => {
      out += chunk;
      const found = out.match(/open (http:\/\/\S+) /);
      if (found) resolve(found[1]);
    });
  });
  const client = { server, frames: 0, onFrame: null, state: async () => (await fetch(`${url}state`)).json() };
  client.socket = new WebSocket(`${url.replace("http", "ws")}live`);
  client.socket.binaryType = "arraybuffer";
  client.socket.onmessage = (event) => {
    if (typeof event.data === "string") return;
    client.frames += 1;
    if (client.onFrame) client.onFrame(event.data);
  };
  await new Promise((resolve) => (client.socket.onopen = resolve));
  client.send = (command) => client.socket.send(JSON.stringify(command));
  return client;
}

// The fastest fluid particle within 0.4 m of the obstacle's centroid, in a frame message.
function speedNearObstacle(buffer) {
  const header = new DataView(buffer, 0, 64);
  const n = header.getUint32(8, true), w = header.getUint32(12, true), b = header.getUint32(16, true);
  const fluid = new Float32Array(buffer, 64, 2 * n);
  const speed = new Float32Array(buffer, 64 + 8 * n, n);
  const obstacle = new Float32Array(buffer, 64 + 12 * n + 8 * w, 2 * b);
  let cx = 0, cy = 0;
  for (let i = 0; i < b; ++i) { cx += obstacle[2 * i] / b; cy += obstacle[2 * i + 1] / b; }
  let fastest = 0;
  for (let i = 0; i < n; ++i) {
    if (Math.hypot(fluid[2 * i] - cx, fluid[2 * i + 1] - cy) < 0.4) fastest = Math.max(fastest, speed[i]);
  }
  return fastest;
}

let client = await startServer(0);
const { send, state } = client;
console.log("| particles | steps/s | sim-s per wall-s | frames/s delivered |");
console.log("| --- | --- | --- | --- |");
const home = await state();
const [homeX, homeY, under] = [home.obstacle_x, home.obstacle_y, home.mean_y];
for (const count of counts) {
  send({ command: "particles", value: count });
  send({ command: "obstacle", x: homeX, y: homeY });
  await sleep(3000);
  const start = await state();
  const framesBefore = client.frames;
  const t0 = Date.now();
  // The obstacle swept to and fro through the water, 30 targets a second.
  while (Date.now() - t0 < seconds * 1000) {
    const phase = ((Date.now() - t0) / 1000) * 0.8 * Math.PI;
    send({ command: "obstacle", x: homeX + 1.0 * Math.sin(phase), y: under });
    await sleep(33);
  }
  const end = await state();
  const wall = (Date.now() - t0) / 1000;
  const steps = (end.steps - start.steps) / wall;
  const simulated = (end.time - start.time) / wall;
  console.log(`| ${end.particles} | ${steps.toFixed(0)} | ${simulated.toFixed(2)} | ${((client.frames - framesBefore) / wall).toFixed(1)} |`);
}

client.socket.close();
client.server.kill("SIGTERM");

// Latency, paced as tide serve runs by default: the obstacle resting in still water is sent
// 0.6 m away; the wall time until the first frame in which the fluid within 0.4 m of it moves
// 0.1 m/s faster than it did before.
client = await startServer(1);
client.send({ command: "obstacle", x: homeX - 0.3, y: under });
await sleep(6000);
const latencies = [];
for (let k = 0; k < 6; ++k) {
  let quiet = 0;
  client.onFrame = (buffer) => { quiet = Math.max(quiet, speedNearObstacle(buffer)); };
  await sleep(300);
  const sent = performance.now();
  const moved = new Promise((resolve) => {
    client.onFrame = (buffer) => { if (speedNearObstacle(buffer) > quiet + 0.1) resolve(performance.now() - sent); };
  });
  client.send({ command: "obstacle", x: homeX + (k % 2 === 0 ? 0.3 : -0.3), y: under });
  latencies.push(await moved);
  client.onFrame = null;
  await sleep(3000);
}
console.log(`latency from an obstacle command to a frame with the fluid moving: ${latencies.map((ms) => ms.toFixed(0)).join(", ")} ms`);
client.socket.close();
client.server.kill("SIGTERM");
