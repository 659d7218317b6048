// Image files decoded in the browser, values untouched: what the browser decodes itself (PNG,
// JPEG, GIF, BMP, WebP) as an ImageBitmap with no colour conversion, Radiance .hdr as float RGB.

import { decodeHdr } from "./hdr.js";

export async function decodeImage(blob, name) {
  if (/\.hdr$/i.test(name)) return decodeHdr(await blob.arrayBuffer(), name);
  if (/\.(exr|tiff?|tga)$/i.test(name)) throw new Error(`${name}: this format is not decoded in the browser`);
  try {
    return { bitmap: await createImageBitmap(blob, { colorSpaceConversion: "none", premultiplyAlpha: "none" }) };
  } catch {
    throw new Error(`${name} is not an image the browser can decode`);
  }
}
