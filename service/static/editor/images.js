// Image files decoded for the preview, values untouched: what the browser decodes itself (PNG,
// JPEG, GIF, BMP, WebP) as an ImageBitmap with no colour conversion, Radiance .hdr and the OpenEXR
// files exr.js reads as float pixels here, and the other OpenEXR files, TIFF and Targa as float
// pixels by the service (OpenImageIO, as the thumbnails read them).

import { decodedImage } from "./api.js";
import { decodeExr, NotReadHere } from "./exr.js";
import { decodeHdr } from "./hdr.js";

const SERVICE_DECODED = /\.(tiff?|tga)$/i;

export async function decodeImage(blob, name) {
  if (/\.(hdr|exr)$/i.test(name)) return decodeFloatImage(blob, name);
  if (SERVICE_DECODED.test(name)) return decodedByService(blob, name);
  try {
    return { bitmap: await createImageBitmap(blob, { colorSpaceConversion: "none", premultiplyAlpha: "none" }) };
  } catch {
    throw new Error(`${name} is not an image the browser can decode`);
  }
}

// A float image ({ width, height, channels, data }), decoded here where it can be; an error names
// the file.
export async function decodeFloatImage(blob, name) {
  if (/\.hdr$/i.test(name)) return decodeHdr(await blob.arrayBuffer(), name);
  if (/\.exr$/i.test(name)) {
    try {
      return await decodeExr(await blob.arrayBuffer(), name);
    } catch (failure) {
      if (!(failure instanceof NotReadHere)) throw failure;
    }
  }
  return decodedByService(blob, name);
}

async function decodedByService(blob, name) {
  const base = name.split("/").pop();
  const image = await decodedImage(blob, base);
  if (image.error) throw new Error(`${name}: ${image.error.code}: ${image.error.message}`);
  return image;
}
