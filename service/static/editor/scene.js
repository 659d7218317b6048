// The preview's scene choices: the mesh (the thumbnails' sphere, a plane, a cube, a dropped
// .obj), the environment (the thumbnails' sky or a dropped .hdr or .exr), its intensity and rotation,
// and the turntable. Dropped scene files join the menus and are chosen at once.

import { irradianceOf } from "./environments.js";
import { decodeFloatImage } from "./images.js";
import { cube, parseObj, plane } from "./meshes.js";

export const SCENE_FILE = /\.(obj|hdr|exr)$/i;

// elements: { mesh, environment, intensity, rotation, turntable } (select, select, range, range, checkbox)
export function installScene(elements, preview, report) {
  const meshes = new Map([["sphere", null], ["plane", plane()], ["cube", cube()]]);
  const environments = new Map([["sky", null]]);
  const fill = (menu, names) => menu.replaceChildren(...[...names.keys()].map((name) => new Option(name, name)));
  fill(elements.mesh, meshes);
  fill(elements.environment, environments);
  elements.mesh.addEventListener("change", () => preview.useMesh(meshes.get(elements.mesh.value)));
  elements.environment.addEventListener("change", () => preview.useEnvironment(environments.get(elements.environment.value)));
  elements.intensity.addEventListener("input", () => preview.choose({ intensity: Number(elements.intensity.value) }));
  elements.rotation.addEventListener("input", () => preview.choose({ rotationDegrees: Number(elements.rotation.value) }));
  elements.turntable.addEventListener("change", () => preview.choose({ turntable: elements.turntable.checked }));

  // Dropped .obj, .hdr and .exr files ({ path, blob }): each added to its menu and chosen.
  return async function addFiles(entries) {
    for (const { path, blob } of entries) {
      try {
        if (/\.obj$/i.test(path)) {
          meshes.set(path, parseObj(await blob.text(), path));
          fill(elements.mesh, meshes);
          elements.mesh.value = path;
          preview.useMesh(meshes.get(path));
        } else {
          const radiance = rgb(await decodeFloatImage(blob, path));
          environments.set(path, { radiance, irradiance: irradianceOf(radiance) });
          fill(elements.environment, environments);
          elements.environment.value = path;
          preview.useEnvironment(environments.get(path));
        }
      } catch (failure) {
        report(failure);
      }
    }
  };
}

// An environment's first three channels (an EXR may have alpha; a grey one is grey in all three).
function rgb({ width, height, channels, data }) {
  if (channels === 3) return { width, height, channels, data };
  const out = new Float32Array(width * height * 3);
  for (let i = 0; i < width * height; i++) {
    for (let c = 0; c < 3; c++) out[i * 3 + c] = data[i * channels + (channels < 3 ? 0 : c)];
  }
  return { width, height, channels: 3, data: out };
}
