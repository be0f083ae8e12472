// Draws a frame with WebGL: every particle a round point of its colour. Null where the browser
// has no WebGL.

import { fitView } from "./view.js";

const VERTEX = `
attribute vec2 a_position;
attribute vec3 a_colour;
uniform vec4 u_map;        // x, y scale and offset from metres to clip space
uniform float u_size;      // point size in pixels
varying vec3 v_colour;
void main() {
  gl_Position = vec4(a_position * u_map.xy + u_map.zw, 0.0, 1.0);
  gl_PointSize = u_size;
  v_colour = a_colour;
}`;

const FRAGMENT = `
precision mediump float;
varying vec3 v_colour;
void main() {
  vec2 r = gl_PointCoord - vec2(0.5);
  if (dot(r, r) > 0.25) discard;
  gl_FragColor = vec4(v_colour, 1.0);
}`;

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
  return shader;
}

export function createWebGLRenderer(canvas) {
  const gl = canvas.getContext("webgl", { antialias: false, preserveDrawingBuffer: true });
  if (!gl) return null;
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, VERTEX));
  gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, FRAGMENT));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
  const position = gl.getAttribLocation(program, "a_position");
  const colour = gl.getAttribLocation(program, "a_colour");
  const map = gl.getUniformLocation(program, "u_map");
  const size = gl.getUniformLocation(program, "u_size");
  const positions = gl.createBuffer(), colours = gl.createBuffer();

  function points(xy, rgb, pixels) {
    const count = xy.length / 2;
    if (count === 0) return;
    gl.bindBuffer(gl.ARRAY_BUFFER, positions);
    gl.bufferData(gl.ARRAY_BUFFER, xy, gl.STREAM_DRAW);
    gl.enableVertexAttribArray(position);
    gl.vertexAttribPointer(position, 2, gl.FLOAT, false, 0, 0);
    gl.bindBuffer(gl.ARRAY_BUFFER, colours);
    gl.bufferData(gl.ARRAY_BUFFER, rgb, gl.STREAM_DRAW);
    gl.enableVertexAttribArray(colour);
    gl.vertexAttribPointer(colour, 3, gl.FLOAT, false, 0, 0);
    gl.uniform1f(size, pixels);
    gl.drawArrays(gl.POINTS, 0, count);
  }

  return {
    kind: "webgl",
    // layers: [{ xy: Float32Array, rgb: Float32Array }], drawn in order.
    draw(frame, layers) {
      const { width, height } = canvas;
      gl.viewport(0, 0, width, height);
      gl.clearColor(0.043, 0.059, 0.078, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
      gl.useProgram(program);
      const view = fitView(frame.view, width, height);
      const [left, top] = view.toPixel(0, 0);
      // clip = 2 px / width - 1, with px = left + x scale (and y flipped).
      gl.uniform4f(map, (2 * view.scale) / width, (2 * view.scale) / height, (2 * left) / width - 1, 1 - (2 * top) / height);
      const pixels = Math.max(1.5, 1.1 * frame.spacing * view.scale);
      for (const layer of layers) points(layer.xy, layer.rgb, pixels);
    },
  };
}
