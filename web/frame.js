// Reads a frame message of tide serve (docs/serve.md, "Frames"): a 64-byte little-endian header
// and float32 arrays.

export const FRAME_MAGIC = 0x48505354; // "TSPH"
export const FRAME_VERSION = 1;
const HEADER_BYTES = 64;
export const COLOUR_FIELDS = ["speed", "density", "pressure"];

export function decodeFrame(buffer) {
  if (buffer.byteLength < HEADER_BYTES) throw new Error(`frame of ${buffer.byteLength} bytes: shorter than its header`);
  const header = new DataView(buffer, 0, HEADER_BYTES);
  const u32 = (word) => header.getUint32(4 * word, true);
  const f32 = (word) => header.getFloat32(4 * word, true);
  if (u32(0) !== FRAME_MAGIC || u32(1) !== FRAME_VERSION) throw new Error("not a version 1 TideSPH frame");
  const fluidCount = u32(2), wallCount = u32(3), obstacleCount = u32(4);
  const floats = 3 * fluidCount + 2 * wallCount + 2 * obstacleCount;
  if (buffer.byteLength !== HEADER_BYTES + 4 * floats) throw new Error("frame length does not match its header");
  let offset = HEADER_BYTES;
  const take = (count) => {
    const array = new Float32Array(buffer, offset, count);
    offset += 4 * count;
    return array;
  };
  return {
    fluidCount, wallCount, obstacleCount,
    colour: COLOUR_FIELDS[u32(5)] ?? "speed",
    colourLow: f32(6), colourHigh: f32(7),
    time: f32(8), steps: u32(9), number: u32(10),
    view: [f32(11), f32(12), f32(13), f32(14)],
    spacing: f32(15),
    fluid: take(2 * fluidCount),
    values: take(fluidCount),
    walls: take(2 * wallCount),
    obstacle: take(2 * obstacleCount),
  };
}
