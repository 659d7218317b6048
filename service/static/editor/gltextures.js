// WebGL2 textures made as the thumbnails' renderer makes them: values untouched (8-bit images
// read as value / 255, no colour conversion: the generated code converts colour spaces), top row
// first, with a full mip chain, and sampled with MaterialX's address modes and filter.

// A decoded image (images.js) as a texture: 8-bit bitmaps as RGBA8, float images as RGBA16F.
export function imageTexture(gl, image) {
  if (image.bitmap) return byteTexture(gl, image.bitmap);
  return floatTexture(gl, toRgba(image.data, image.channels), image.width, image.height);
}

function byteTexture(gl, bitmap) {
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);
  gl.pixelStorei(gl.UNPACK_PREMULTIPLY_ALPHA_WEBGL, false);
  gl.pixelStorei(gl.UNPACK_COLORSPACE_CONVERSION_WEBGL, gl.NONE);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, bitmap);
  gl.generateMipmap(gl.TEXTURE_2D);
  return texture;
}

// RGBA float data as a filterable half-float texture with its mip chain, box-filtered here
// (WebGL2 cannot generate mipmaps for float formats it cannot render to).
export function floatTexture(gl, rgba, width, height) {
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  let level = 0, w = width, h = height, data = rgba;
  for (;;) {
    gl.texImage2D(gl.TEXTURE_2D, level, gl.RGBA16F, w, h, 0, gl.RGBA, gl.FLOAT, data);
    if (w === 1 && h === 1) break;
    [data, w, h] = halve(data, w, h);
    level += 1;
  }
  return texture;
}

// 1 x 1 of one colour: an image node's default where its file cannot be used.
export function constantTexture(gl, rgba) {
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA16F, 1, 1, 0, gl.RGBA, gl.FLOAT, new Float32Array(rgba));
  return texture;
}

// Sampler state of the bound texture: wrap per MaterialX address mode (constant has no border
// colour in WebGL2; it clamps to the edge and the generated code fades to the default colour
// itself), nearest for "closest", trilinear otherwise (GL has no cubic filter).
export function applySampling(gl, { wrapU, wrapV, closest }) {
  const wrap = { constant: gl.CLAMP_TO_EDGE, clamp: gl.CLAMP_TO_EDGE, periodic: gl.REPEAT, mirror: gl.MIRRORED_REPEAT };
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, wrap[wrapU] ?? gl.REPEAT);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, wrap[wrapV] ?? gl.REPEAT);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, closest ? gl.NEAREST_MIPMAP_NEAREST : gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, closest ? gl.NEAREST : gl.LINEAR);
}

// grey and grey-alpha images read as grey (RRR1, RRRG), as the renderer swizzles them
export function toRgba(pixels, channels) {
  const count = pixels.length / channels, out = new Float32Array(count * 4);
  const alpha = channels === 2 || channels === 4 ? channels - 1 : -1;
  for (let i = 0; i < count; i++) {
    for (let c = 0; c < 3; c++) out[i * 4 + c] = pixels[i * channels + (channels < 3 ? 0 : c)];
    out[i * 4 + 3] = alpha < 0 ? 1 : pixels[i * channels + alpha];
  }
  return out;
}

function halve(data, w, h) {
  const nw = Math.max(1, w >> 1), nh = Math.max(1, h >> 1), out = new Float32Array(nw * nh * 4);
  const sx = w / nw, sy = h / nh;
  for (let y = 0; y < nh; y++) {
    for (let x = 0; x < nw; x++) {
      for (let c = 0; c < 4; c++) {
        let sum = 0;
        for (let dy = 0; dy < sy; dy++) for (let dx = 0; dx < sx; dx++) sum += data[((y * sy + dy) * w + x * sx + dx) * 4 + c];
        out[(y * nw + x) * 4 + c] = sum / (sx * sy);
      }
    }
  }
  return [out, nw, nh];
}
