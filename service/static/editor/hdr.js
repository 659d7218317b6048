// Radiance .hdr (RGBE) images decoded in the browser, for dropped environments and textures:
// float32 RGB rows top first, as OpenImageIO reads them for the thumbnails.

export function decodeHdr(buffer, name) {
  const bytes = new Uint8Array(buffer);
  let at = 0;
  const line = () => {
    const start = at;
    while (at < bytes.length && bytes[at] !== 0x0a) at++;
    return new TextDecoder().decode(bytes.subarray(start, at++));
  };
  if (!/^#\?(RADIANCE|RGBE)/.test(line())) throw new Error(`${name} is not a Radiance HDR image`);
  for (let text = line(); text !== ""; text = line()) {
    if (at >= bytes.length) throw new Error(`${name}: its header has no end`);
    if (text.startsWith("FORMAT=") && text !== "FORMAT=32-bit_rle_rgbe") throw new Error(`${name}: ${text} is not read`);
  }
  const size = /^-Y (\d+) \+X (\d+)$/.exec(line());
  if (!size) throw new Error(`${name}: only top-to-bottom, left-to-right images (-Y h +X w) are read`);
  const height = Number(size[1]), width = Number(size[2]);
  const rgbe = new Uint8Array(width * 4);
  const out = new Float32Array(width * height * 3);
  for (let y = 0; y < height; y++) {
    at = scanline(bytes, at, rgbe, width, name);
    for (let x = 0; x < width; x++) {
      const e = rgbe[x * 4 + 3], scale = e ? 2 ** (e - 136) : 0;
      for (let c = 0; c < 3; c++) out[(y * width + x) * 3 + c] = rgbe[x * 4 + c] * scale;
    }
  }
  return { width, height, channels: 3, data: out };
}

// One scanline into `rgbe`: run-length encoded per component (the new format), or flat.
function scanline(bytes, at, rgbe, width, name) {
  const rle = width >= 8 && width < 32768 && bytes[at] === 2 && bytes[at + 1] === 2 && !(bytes[at + 2] & 0x80);
  if (!rle) {
    if (at + width * 4 > bytes.length) throw new Error(`${name} ends early`);
    rgbe.set(bytes.subarray(at, at + width * 4));
    return at + width * 4;
  }
  at += 4;
  for (let c = 0; c < 4; c++) {
    for (let x = 0; x < width;) {
      if (at >= bytes.length) throw new Error(`${name} ends early`);
      let count = bytes[at++];
      const run = count > 128;
      if (run) count -= 128;
      if (count === 0 || x + count > width) throw new Error(`${name}: a damaged scanline`);
      for (let i = 0; i < count; i++) rgbe[(x + i) * 4 + c] = run ? bytes[at] : bytes[at + i];
      at += run ? 1 : count;
      x += count;
    }
  }
  return at;
}
