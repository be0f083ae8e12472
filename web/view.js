// The map between the simulation's metres and the canvas's pixels: the domain fitted into the
// canvas, centred, y up.

export function fitView(view, width, height) {
  const [x0, y0, x1, y1] = view;
  const scale = Math.min(width / (x1 - x0), height / (y1 - y0));
  const left = (width - scale * (x1 - x0)) / 2;
  const bottom = (height - scale * (y1 - y0)) / 2;
  return {
    scale,
    toPixel: (x, y) => [left + (x - x0) * scale, height - bottom - (y - y0) * scale],
    toWorld: (px, py) => [x0 + (px - left) / scale, y0 + (height - bottom - py) / scale],
  };
}

// The colour map: deep blue through cyan and yellow to red, for t in [0, 1].
const STOPS = [
  [0.0, [0.12, 0.23, 0.62]],
  [0.35, [0.16, 0.65, 0.85]],
  [0.65, [0.95, 0.85, 0.3]],
  [1.0, [0.85, 0.2, 0.15]],
];

export function colourAt(t) {
  const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0));
  for (let k = 1; k < STOPS.length; ++k) {
    if (x <= STOPS[k][0]) {
      const [a, ca] = STOPS[k - 1], [b, cb] = STOPS[k];
      const s = (x - a) / (b - a);
      return [0, 1, 2].map((i) => ca[i] + s * (cb[i] - ca[i]));
    }
  }
  return STOPS[STOPS.length - 1][1];
}

export const WALL_COLOUR = [0.45, 0.5, 0.57];
export const OBSTACLE_COLOUR = [0.93, 0.93, 0.96];
