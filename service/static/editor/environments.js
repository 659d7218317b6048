// A dropped lat-long environment (a decoded .hdr) made into the two maps the shaders read: the
// radiance map itself, and the irradiance map as the renderer computes it (its order-2 spherical
// harmonics, cosine-convolved, divided by pi), in the library's lat-long parameterisation
// (mx_envmap_uv: u = atan(x, -z) / 2pi + 1/2, v = 1/2 - asin(y) / pi, the top row first).

const IRRADIANCE_SIZE = [64, 128];  // rows, columns: the irradiance varies slowly
const PROJECTION_ROWS = 256;         // the radiance is box-filtered to at most this many rows first
const BAND_WEIGHTS = [Math.PI, 2 * Math.PI / 3, 2 * Math.PI / 3, 2 * Math.PI / 3, Math.PI / 4, Math.PI / 4,
  Math.PI / 4, Math.PI / 4, Math.PI / 4];

export function irradianceOf({ width, height, data }) {
  const step = Math.max(1, Math.ceil(height / PROJECTION_ROWS));
  const rows = Math.floor(height / step), columns = Math.floor(width / step);
  const coefficients = Array.from({ length: 9 }, () => [0, 0, 0]);
  for (let j = 0; j < rows; j++) {
    for (let i = 0; i < columns; i++) {
      const colour = [0, 0, 0];
      for (let dy = 0; dy < step; dy++) {
        for (let dx = 0; dx < step; dx++) {
          const at = ((j * step + dy) * width + i * step + dx) * 3;
          for (let c = 0; c < 3; c++) colour[c] += data[at + c] / (step * step);
        }
      }
      const { direction, cosine } = directionOf(i, j, columns, rows);
      const solidAngle = cosine * (2 * Math.PI / columns) * (Math.PI / rows);
      basis(direction).forEach((y, k) => { for (let c = 0; c < 3; c++) coefficients[k][c] += colour[c] * y * solidAngle; });
    }
  }
  const [h, w] = IRRADIANCE_SIZE, out = new Float32Array(w * h * 3);
  for (let j = 0; j < h; j++) {
    for (let i = 0; i < w; i++) {
      const y = basis(directionOf(i, j, w, h).direction);
      for (let c = 0; c < 3; c++) {
        let sum = 0;
        for (let k = 0; k < 9; k++) sum += BAND_WEIGHTS[k] * coefficients[k][c] * y[k];
        out[(j * w + i) * 3 + c] = Math.max(0, sum / Math.PI);
      }
    }
  }
  return { width: w, height: h, channels: 3, data: out };
}

function directionOf(i, j, columns, rows) {
  const latitude = (0.5 - (j + 0.5) / rows) * Math.PI, longitude = ((i + 0.5) / columns - 0.5) * 2 * Math.PI;
  const cosine = Math.cos(latitude);
  return { direction: [cosine * Math.sin(longitude), Math.sin(latitude), -cosine * Math.cos(longitude)], cosine };
}

function basis([x, y, z]) {
  return [0.282095, 0.488603 * y, 0.488603 * z, 0.488603 * x, 1.092548 * x * y, 1.092548 * y * z,
          0.315392 * (3 * z * z - 1), 1.092548 * x * z, 0.546274 * (x * x - y * y)];
}
