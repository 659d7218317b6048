// Meshes the preview can draw besides the thumbnails' sphere (which the service sends): the
// renderer's plane, a cube, and a dropped Wavefront .obj, centred and scaled into the unit sphere
// as the renderer loads one. Each is { name, streams: { i_position: Float32Array, ... }, indices }.

export function plane() {
  const position = [-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0];
  return mesh("plane", position, repeat([0, 0, 1], 4), [0, 0, 1, 0, 1, 1, 0, 1], repeat([1, 0, 0], 4), [0, 1, 2, 0, 2, 3]);
}

// A cube of side 1.2, each face with its own normal, tangent and full uv square.
export function cube() {
  const faces = [  // normal, tangent (u direction); bitangent = normal x tangent is v
    [[0, 0, 1], [1, 0, 0]], [[0, 0, -1], [-1, 0, 0]], [[1, 0, 0], [0, 0, -1]],
    [[-1, 0, 0], [0, 0, 1]], [[0, 1, 0], [1, 0, 0]], [[0, -1, 0], [1, 0, 0]]];
  const position = [], normal = [], uv = [], tangent = [], indices = [];
  const half = 0.6;
  faces.forEach(([n, t], face) => {
    const b = cross(n, t);
    for (const [su, sv] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
      for (let c = 0; c < 3; c++) position.push(half * (n[c] + su * t[c] + sv * b[c]));
      normal.push(...n);
      tangent.push(...t);
      uv.push((su + 1) / 2, (sv + 1) / 2);
    }
    indices.push(face * 4, face * 4 + 1, face * 4 + 2, face * 4, face * 4 + 2, face * 4 + 3);
  });
  return mesh("cube", position, normal, uv, tangent, indices);
}

// v, vt, vn and polygonal f (fanned into triangles); normals computed (area weighted) when
// absent, tangents from the first uv set, else any direction across the normal.
export function parseObj(text, name) {
  const v = [], vt = [], vn = [], corners = [];
  text.split("\n").forEach((line, number) => {
    const [tag, ...args] = line.trim().split(/\s+/);
    if (tag === "v") v.push(args.slice(0, 3).map(Number));
    else if (tag === "vt") vt.push(args.slice(0, 2).map(Number));
    else if (tag === "vn") vn.push(args.slice(0, 3).map(Number));
    else if (tag === "f") {
      const face = args.map((corner) => corner.split("/").map((index, k) => {
        const i = parseInt(index, 10), count = [v, vt, vn][k].length;
        return Number.isNaN(i) ? null : i < 0 ? count + i : i - 1;
      }));
      if (face.some(([p]) => p === null || p < 0 || p >= v.length)) throw new Error(`${name}:${number + 1}: a face names no vertex`);
      for (let i = 1; i + 1 < face.length; i++) corners.push(face[0], face[i], face[i + 1]);
    }
  });
  if (!corners.length) throw new Error(`${name} has no faces`);
  const centre = [0, 1, 2].map((c) => (Math.min(...v.map((p) => p[c])) + Math.max(...v.map((p) => p[c]))) / 2);
  const radius = Math.max(...v.map((p) => Math.hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]))) || 1;
  const position = corners.flatMap(([p]) => v[p].map((x, c) => (x - centre[c]) / radius));
  const uv = corners.flatMap(([, t]) => (t !== null && vt[t] ? vt[t] : [0, 0]));
  let normal = corners.flatMap(([, , n]) => (n !== null && vn[n] ? normalize(vn[n]) : [0, 0, 0]));
  if (corners.some(([, , n]) => n === null || !vn[n])) normal = faceNormals(position);
  const tangent = tangents(position, normal, uv);
  return mesh(name, position, normal, uv, tangent, corners.map((_, i) => i));
}

function faceNormals(position) {
  const out = [];
  for (let i = 0; i < position.length; i += 9) {
    const a = position.slice(i, i + 3), b = position.slice(i + 3, i + 6), c = position.slice(i + 6, i + 9);
    const n = normalize(cross(sub(b, a), sub(c, a)));
    out.push(...n, ...n, ...n);
  }
  return out;
}

function tangents(position, normal, uv) {
  const out = [];
  for (let i = 0; i < position.length / 3; i += 3) {
    const p = [0, 1, 2].map((k) => position.slice((i + k) * 3, (i + k) * 3 + 3));
    const t = [0, 1, 2].map((k) => uv.slice((i + k) * 2, (i + k) * 2 + 2));
    const e1 = sub(p[1], p[0]), e2 = sub(p[2], p[0]);
    const du1 = t[1][0] - t[0][0], dv1 = t[1][1] - t[0][1], du2 = t[2][0] - t[0][0], dv2 = t[2][1] - t[0][1];
    const det = du1 * dv2 - du2 * dv1;
    for (let k = 0; k < 3; k++) {
      const n = normal.slice((i + k) * 3, (i + k) * 3 + 3);
      let tangent = Math.abs(det) > 1e-12 ? e1.map((x, c) => (x * dv2 - e2[c] * dv1) / det) : cross(Math.abs(n[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0], n);
      const along = dot(tangent, n);
      tangent = normalize(tangent.map((x, c) => x - along * n[c]));
      out.push(...tangent);
    }
  }
  return out;
}

function mesh(name, position, normal, uv, tangent, indices) {
  const bitangent = [];
  for (let i = 0; i < normal.length; i += 3) bitangent.push(...cross(normal.slice(i, i + 3), tangent.slice(i, i + 3)));
  const streams = { i_position: position, i_normal: normal, i_texcoord_0: uv, i_tangent: tangent, i_bitangent: bitangent };
  return { name, streams: Object.fromEntries(Object.entries(streams).map(([k, s]) => [k, new Float32Array(s)])),
           components: { i_position: 3, i_normal: 3, i_texcoord_0: 2, i_tangent: 3, i_bitangent: 3 },
           indices: new Uint32Array(indices) };
}

const repeat = (values, n) => Array.from({ length: n }, () => values).flat();
const sub = (a, b) => a.map((x, i) => x - b[i]);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const normalize = (a) => {
  const length = Math.hypot(...a) || 1;
  return a.map((x) => x / length);
};
