// The file textures of a record, found and sampled as the thumbnails' renderer does: each
// filename uniform's file from the files dropped on the page, else from the service
// (GET /v1/textures, the texture roots only); its sampling from its image node's other inputs
// (`uaddressmode`, `vaddressmode`, `filtertype`), read live so a control changes it; a file
// that cannot be used is drawn in the node's `default` colour, with the reason kept.

import { textureFile } from "./api.js";
import { decodeImage } from "./images.js";
import { constantTexture, imageTexture } from "./gltextures.js";

const ADDRESS_MODES = ["constant", "clamp", "periodic", "mirror"];
const FILTER_TYPES = ["closest", "linear", "cubic"];
const SAMPLING_INPUTS = ["uaddressmode", "vaddressmode", "filtertype", "default"];

// [{ name (the sampler), file, inputs: { uaddressmode: variable, ... }, fallback }] of a record.
export function textureRequests(record) {
  const variables = Object.values(record.blocks ?? {}).flatMap((stage) => stage.PublicUniforms ?? []);
  return variables.filter((variable) => variable.type === "filename" && variable.path).map((variable) => {
    const node = nodePrefix(variable.path);
    const inputs = {};
    for (const input of SAMPLING_INPUTS) inputs[input] = variables.find((v) => v.path === node + input) ?? null;
    return { name: variable.name, file: variable.value, inputs, fallback: variable.fallback };
  });
}

// `NG/image1/file` -> `NG/image1/`; a USD attribute `/Looks/Image.inputs:file` -> `/Looks/Image.inputs:`
function nodePrefix(path) {
  const usd = path.lastIndexOf(".inputs:");
  return usd >= 0 ? path.slice(0, usd + ".inputs:".length) : path.slice(0, path.lastIndexOf("/") + 1);
}

// The sampling of a request under the current values (uniform name -> value).
export function samplingOf(request, values) {
  const value = (input) => {
    const variable = request.inputs[input];
    return variable ? values.get(variable.name) ?? variable.value : undefined;
  };
  return { wrapU: enumName(value("uaddressmode"), ADDRESS_MODES) ?? "periodic",
           wrapV: enumName(value("vaddressmode"), ADDRESS_MODES) ?? "periodic",
           closest: enumName(value("filtertype"), FILTER_TYPES) === "closest" };
}

function enumName(value, names) {
  if (typeof value === "string" && names.includes(value.trim().toLowerCase())) return value.trim().toLowerCase();
  return Number.isInteger(value) && value >= 0 && value < names.length ? names[value] : null;
}

// An image node's `default` as RGBA: a float is grey, missing channels 0, alpha 1; black without one.
export function defaultColour(request, values) {
  const variable = request.inputs.default;
  let v = variable ? values.get(variable.name) ?? variable.value : request.fallback;
  if (v === null || v === undefined) v = [0, 0, 0];
  if (!Array.isArray(v)) v = [Number(v), Number(v), Number(v)];
  return [...[...v, 0, 0, 0].slice(0, 3), v[3] ?? 1].map(Number);
}

export class TextureLoader {
  constructor(gl, files) {
    this.gl = gl;
    this.files = files;
    this.loaded = new Map();  // file reference + drop version -> Promise<{ texture, from, problem }>
    this.constants = new Map();
  }

  // The texture of a file reference: { texture, from: "dropped" | "service", problem: null },
  // or { texture: null, problem } saying why there is none.
  load(file) {
    if (typeof file !== "string" || file === "") return Promise.resolve({ texture: null, problem: null });
    const key = `${this.files.version}\u0000${file}`;
    if (!this.loaded.has(key)) this.loaded.set(key, this.read(file));
    return this.loaded.get(key);
  }

  async read(file) {
    const dropped = this.files.find(file);
    let blob = dropped?.blob, name = dropped?.path ?? file;
    if (!blob) {
      const answer = await textureFile(file);
      if (answer.error) return { texture: null, problem: `${file}: ${answer.error.code}: ${answer.error.message}` };
      blob = answer.blob;
    }
    try {
      return { texture: imageTexture(this.gl, await decodeImage(blob, name)), from: dropped ? "dropped" : "service", problem: null };
    } catch (failure) {
      return { texture: null, problem: failure.message };
    }
  }

  constant(rgba) {
    const key = rgba.join(",");
    if (!this.constants.has(key)) this.constants.set(key, constantTexture(this.gl, rgba));
    return this.constants.get(key);
  }
}
