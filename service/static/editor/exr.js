// OpenEXR images decoded in the browser, so a dropped .exr needs no request: single-part scanline
// files with the compressions writers use by default (OpenImageIO and OpenEXR write ZIP) or that
// are lossless byte streams (none, RLE, ZIPS, ZIP), HALF, FLOAT or UINT channels named R, G, B, A
// or Y, A, sampled 1:1. Written from the OpenEXR file layout document. Anything else (PIZ, PXR24,
// B44, DWA, tiled, multi-part, deep, other channel sets) is `NotReadHere`, which images.js hands
// to the service's OpenImageIO decoder. Pixels come out as OpenImageIO reads them for the
// thumbnails: float32, top row (the data window's yMin) first, channels R, G, B, A.

export class NotReadHere extends Error {}

const MAGIC = 20000630;
const TILED = 0x200, NON_IMAGE = 0x800, MULTI_PART = 0x1000;
// [name, scanlines per chunk] by the header's compression byte, of those read here
const COMPRESSIONS = { 0: ["none", 1], 1: ["RLE", 1], 2: ["ZIPS", 1], 3: ["ZIP", 16] };
const UINT = 0, HALF = 1, FLOAT = 2;
const BYTES = { [UINT]: 4, [HALF]: 2, [FLOAT]: 4 };
// the channel sets read, each in the order the page's images hold them
const LAYOUTS = ["R,G,B,A", "R,G,B", "Y,A", "Y"].map((names) => names.split(","));
// the renderer's default bound on an image's values (SHADERGEN_MAX_IMAGE_VALUES): a damaged or
// hostile header must not make the page allocate gigabytes
const MAX_VALUES = 1 << 26;

// { width, height, channels, data: Float32Array }; throws NotReadHere, or an Error naming what is
// wrong with the file.
export async function decodeExr(buffer, name) {
  const bytes = new Uint8Array(buffer), view = new DataView(buffer);
  const reader = { at: 0, need(n) { if (this.at + n > bytes.length) throw new Error(`${name} ends early`); } };
  reader.need(8);
  if (view.getInt32(0, true) !== MAGIC) throw new Error(`${name} is not an OpenEXR image`);
  const flags = view.getUint32(4, true);
  if (flags & (TILED | NON_IMAGE | MULTI_PART)) throw new NotReadHere(`${name}: tiled, deep or multi-part`);
  reader.at = 8;
  const header = readHeader(bytes, view, reader, name);
  const { channels, compression, dataWindow: [xMin, yMin, xMax, yMax] } = header;
  const kind = COMPRESSIONS[compression];
  if (!kind) throw new NotReadHere(`${name}: compression ${compression}`);
  const layout = LAYOUTS.find((names) => names.length === channels.length && names.every((n) => channels.some((c) => c.name === n)));
  if (!layout || channels.some((c) => c.xSampling !== 1 || c.ySampling !== 1)) {
    throw new NotReadHere(`${name}: channels ${channels.map((c) => c.name).join(", ")}`);
  }
  const width = xMax - xMin + 1, height = yMax - yMin + 1;
  if (width < 1 || height < 1) throw new Error(`${name}: an empty data window`);
  if (width * height * layout.length > MAX_VALUES) {
    throw new Error(`${name}: ${width} x ${height} x ${layout.length} values, more than the ${MAX_VALUES} read`);
  }
  const [, lines] = kind;
  const rowBytes = channels.reduce((sum, c) => sum + width * BYTES[c.type], 0);
  const chunks = Math.ceil(height / lines);
  reader.need(chunks * 8);
  const out = new Float32Array(width * height * layout.length);
  const place = channels.map((c) => layout.indexOf(c.name));  // file order (alphabetical) to ours
  await Promise.all(Array.from({ length: chunks }, async (_, i) => {
    const offset = Number(view.getBigUint64(reader.at + i * 8, true));
    if (offset + 8 > bytes.length) throw new Error(`${name}: chunk ${i} lies past the end of the file`);
    const y = view.getInt32(offset, true), size = view.getInt32(offset + 4, true);
    const rows = Math.min(lines, yMax - y + 1);
    if (y < yMin || y > yMax || (y - yMin) % lines || size < 0 || offset + 8 + size > bytes.length) {
      throw new Error(`${name}: chunk ${i} is damaged`);
    }
    const packed = bytes.subarray(offset + 8, offset + 8 + size), expected = rows * rowBytes;
    // a chunk that would not shrink is stored as it is, whatever the compression
    const raw = kind[0] === "none" || size === expected ? packed : await unpack(kind[0], packed, expected, name);
    if (raw.length !== expected) throw new Error(`${name}: chunk ${i} holds ${raw.length} bytes, not ${expected}`);
    const data = new DataView(raw.buffer, raw.byteOffset, raw.length);
    let at = 0;
    for (let row = y - yMin; row < y - yMin + rows; row++) {
      channels.forEach((channel, c) => {
        for (let x = 0; x < width; x++, at += BYTES[channel.type]) {
          out[(row * width + x) * layout.length + place[c]] = value(data, at, channel.type);
        }
      });
    }
  }));
  return { width, height, channels: layout.length, data: out };
}

function readHeader(bytes, view, reader, name) {
  const text = () => {
    const start = reader.at;
    while (reader.at < bytes.length && bytes[reader.at] !== 0) reader.at++;
    reader.need(1);
    return new TextDecoder().decode(bytes.subarray(start, reader.at++));
  };
  const found = {};
  for (let attribute = text(); attribute !== ""; attribute = text()) {
    const type = text();
    reader.need(4);
    const size = view.getInt32(reader.at, true);
    reader.at += 4;
    reader.need(size);
    if (attribute === "channels" && type === "chlist") found.channels = channelList(bytes, view, reader.at, reader.at + size, name);
    else if (attribute === "compression" && type === "compression") found.compression = bytes[reader.at];
    else if (attribute === "dataWindow" && type === "box2i") found.dataWindow = [0, 4, 8, 12].map((o) => view.getInt32(reader.at + o, true));
    reader.at += size;
  }
  for (const required of ["channels", "compression", "dataWindow"]) {
    if (found[required] === undefined) throw new Error(`${name}: its header has no ${required}`);
  }
  return found;
}

function channelList(bytes, view, at, end, name) {
  const channels = [];
  while (at < end && bytes[at] !== 0) {
    const start = at;
    while (at < end && bytes[at] !== 0) at++;
    if (at + 17 > end) throw new Error(`${name}: a damaged channel list`);
    const channelName = new TextDecoder().decode(bytes.subarray(start, at));
    const type = view.getInt32(at + 1, true);
    if (!(type in BYTES)) throw new Error(`${name}: channel ${channelName} has pixel type ${type}`);
    channels.push({ name: channelName, type, xSampling: view.getInt32(at + 9, true), ySampling: view.getInt32(at + 13, true) });
    at += 17;  // the name's end, type, pLinear and 3 reserved bytes, x and y sampling
  }
  return channels;
}

function value(data, at, type) {
  if (type === FLOAT) return data.getFloat32(at, true);
  if (type === UINT) return data.getUint32(at, true) / 0xffffffff;  // OpenImageIO reads unsigned ints normalised
  return half(data.getUint16(at, true));
}

function half(bits) {
  const sign = bits & 0x8000 ? -1 : 1, exponent = (bits >> 10) & 0x1f, mantissa = bits & 0x3ff;
  if (exponent === 0) return sign * mantissa * 2 ** -24;
  if (exponent === 31) return mantissa ? NaN : sign * Infinity;
  return sign * (1 + mantissa / 1024) * 2 ** (exponent - 15);
}

// RLE and ZIP(S) store the bytes reordered (the even bytes, then the odd ones) and as differences
// from the byte before (plus 128), then run-length coded or deflated (zlib).
async function unpack(kind, packed, expected, name) {
  const coded = kind === "RLE" ? runLengthDecoded(packed, expected, name) : await inflated(packed, name);
  if (coded.length !== expected) return coded;
  for (let i = 1; i < coded.length; i++) coded[i] = coded[i - 1] + coded[i] - 128;
  const out = new Uint8Array(expected), odd = (expected + 1) >> 1;
  for (let i = 0; i < expected; i++) out[i] = coded[(i & 1 ? odd : 0) + (i >> 1)];
  return out;
}

function runLengthDecoded(packed, expected, name) {
  const out = new Uint8Array(expected);
  let at = 0, to = 0;
  while (at < packed.length) {
    const count = (packed[at++] << 24) >> 24;  // a signed byte
    const literal = count < 0, length = literal ? -count : count + 1;
    if (to + length > expected || at + (literal ? length : 1) > packed.length) throw new Error(`${name}: damaged RLE data`);
    if (literal) out.set(packed.subarray(at, at + length), to);
    else out.fill(packed[at], to, to + length);
    at += literal ? length : 1;
    to += length;
  }
  return out.subarray(0, to);
}

async function inflated(packed, name) {
  try {
    const stream = new Blob([packed]).stream().pipeThrough(new DecompressionStream("deflate"));
    return new Uint8Array(await new Response(stream).arrayBuffer());
  } catch {
    throw new Error(`${name}: damaged ZIP data`);
  }
}
