// The service's HTTP API as the editor uses it. Every answer is either a record or the
// contract's error object; network failures become error objects too, so callers show one kind.

export const traffic = { generate: 0, decode: 0 };  // requests sent, for the page's tests and status line

export async function generate(document, { element = null, target = "essl", interface: mode = "complete", source = true } = {}) {
  traffic.generate += 1;
  const body = JSON.stringify({ document, element, target, interface: mode, source });
  return answer(await request("v1/generate", { method: "POST", headers: { "content-type": "application/json" }, body }));
}

// A USD layer or usdz package (whose textures are its own members) generated as it is, the
// options in the query.
export async function generateUsd(blob, media, { element = null, target = "essl", interface: mode = "complete", source = true } = {}) {
  traffic.generate += 1;
  const query = new URLSearchParams({ target, interface: mode, source: String(source) });
  if (element) query.set("element", element);
  const init = { method: "POST", headers: { "content-type": media }, body: blob };
  return answer(await request(`v1/generate?${query}`, init));
}

export async function nodedefs() {
  return answer(await request("v1/nodedefs"));
}

export async function previewScene() {
  return answer(await request("v1/preview/scene"));
}

export async function previewArray(name, kind = Float32Array) {
  const response = await request(`v1/preview/arrays/${encodeURIComponent(name)}`);
  if (!response.ok) throw new Error(`preview array ${name}: HTTP ${response.status}`);
  return new kind(await response.arrayBuffer());
}

// A texture the document names, from the service's texture roots: { blob } or the error object.
export async function textureFile(name) {
  const response = await request(`v1/textures?path=${encodeURIComponent(name)}`);
  if (!response.ok) return answer(response);
  return { blob: await response.blob() };
}

// An image file the page does not decode (TIFF, TGA, the OpenEXR files exr.js leaves) decoded by
// the service, nothing stored: { width, height, channels, data: Float32Array } or the error object.
export async function decodedImage(blob, name) {
  traffic.decode += 1;
  const init = { method: "POST", headers: { "content-type": "application/octet-stream" }, body: blob };
  const response = await request(`v1/images/decode?name=${encodeURIComponent(name)}`, init);
  if (!response.ok) return answer(response);
  const size = (header) => Number(response.headers.get(header));
  return { width: size("X-Image-Width"), height: size("X-Image-Height"), channels: size("X-Image-Channels"),
           data: new Float32Array(await response.arrayBuffer()) };
}

export async function exampleDocument(name) {
  const response = await request(`examples/${encodeURIComponent(name)}`, {}, "");
  if (!response.ok) throw new Error(`example ${name}: HTTP ${response.status}`);
  return response.text();
}

// Paths are relative to the service's root (the editor lives at /editor/); `base` "" keeps them
// relative to the editor.
function request(path, init = {}, base = "/") {
  return fetch(base + path, init).catch((failure) => ({
    ok: false, status: 0,
    json: async () => ({ error: { code: "unreachable", message: String(failure), where: null } }),
  }));
}

async function answer(response) {
  let body;
  try {
    body = await response.json();
  } catch {
    body = { error: { code: "invalid_response", message: `HTTP ${response.status} without a JSON body`, where: null } };
  }
  return body;
}
