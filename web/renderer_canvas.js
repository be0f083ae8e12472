// Draws a frame on a 2D canvas: the fallback where the browser has no WebGL.

import { fitView } from "./view.js";

export function createCanvasRenderer(canvas) {
  const context = canvas.getContext("2d");
  const hex = (v) => Math.round(255 * Math.min(1, Math.max(0, v)));
  return {
    kind: "canvas2d",
    draw(frame, layers) {
      const { width, height } = canvas;
      context.fillStyle = "#0b0f14";
      context.fillRect(0, 0, width, height);
      const view = fitView(frame.view, width, height);
      const size = Math.max(1.5, 1.1 * frame.spacing * view.scale);
      for (const layer of layers) {
        for (let i = 0; i < layer.xy.length / 2; ++i) {
          const [px, py] = view.toPixel(layer.xy[2 * i], layer.xy[2 * i + 1]);
          context.fillStyle = `rgb(${hex(layer.rgb[3 * i])},${hex(layer.rgb[3 * i + 1])},${hex(layer.rgb[3 * i + 2])})`;
          context.fillRect(px - size / 2, py - size / 2, size, size);
        }
      }
    },
  };
}
