// The scene choices as uniforms over the thumbnails' scene: the environment's intensity and its
// rotation about the vertical (u_envMatrix), and the turntable's rotation of the object (every
// world matrix and the products with view and projection). Matrices are column-major arrays.

const WORLD_MATRICES = ["u_worldMatrix", "u_worldInverseMatrix", "u_worldTransposeMatrix", "u_worldInverseTransposeMatrix",
  "u_worldViewMatrix", "u_worldViewProjectionMatrix"];

// scene: the service's scene uniforms; choices: { intensity, rotationDegrees, turntableDegrees }
export function sceneOverrides(scene, { intensity = 1, rotationDegrees = 0, turntableDegrees = 0, radianceMips = null }) {
  const out = { u_envLightIntensity: [scene.u_envLightIntensity[0] * intensity],
                u_envMatrix: multiply(scene.u_envMatrix, rotationY(rotationDegrees)) };
  if (radianceMips !== null) out.u_envRadianceMips = [radianceMips];
  const world = rotationY(turntableDegrees), inverse = transpose(world);  // a rotation's inverse
  const values = { u_worldMatrix: world, u_worldInverseMatrix: inverse, u_worldTransposeMatrix: inverse,
                   u_worldInverseTransposeMatrix: world, u_worldViewMatrix: multiply(scene.u_viewMatrix, world),
                   u_worldViewProjectionMatrix: multiply(scene.u_viewProjectionMatrix, world) };
  for (const name of WORLD_MATRICES) out[name] = values[name];
  return out;
}

function rotationY(degrees) {
  const a = (degrees * Math.PI) / 180, c = Math.cos(a), s = Math.sin(a);
  return [c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1];
}

function multiply(a, b) {  // a x b, column-major 4 x 4
  const out = new Array(16).fill(0);
  for (let col = 0; col < 4; col++) {
    for (let row = 0; row < 4; row++) {
      for (let k = 0; k < 4; k++) out[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
    }
  }
  return out;
}

function transpose(m) {
  return m.map((_, i) => m[(i % 4) * 4 + Math.floor(i / 4)]);
}
