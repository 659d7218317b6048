// The members of a .zip or .usdz dropped on the page, read in the browser: the central directory
// names them, each is stored (usdz) or deflated (DecompressionStream), nothing is sent anywhere.

const END_OF_DIRECTORY = 0x06054b50, DIRECTORY_ENTRY = 0x02014b50, LOCAL_HEADER = 0x04034b50;
const STORED = 0, DEFLATED = 8;
const MAX_MEMBERS = 10000;  // a directory claiming more is not a package a person dropped

// [{ path, blob }] of the archive's files (folders skipped); throws an Error naming what is wrong.
export async function unzip(blob, name) {
  const bytes = new DataView(await blob.arrayBuffer());
  const end = findEnd(bytes, name);
  const count = bytes.getUint16(end + 10, true);
  if (count > MAX_MEMBERS) throw new Error(`${name}: ${count} members, more than ${MAX_MEMBERS}`);
  let at = bytes.getUint32(end + 16, true);
  const members = [];
  for (let i = 0; i < count; i++) {
    if (at + 46 > bytes.byteLength || bytes.getUint32(at, true) !== DIRECTORY_ENTRY) {
      throw new Error(`${name}: its directory is damaged at entry ${i}`);
    }
    const method = bytes.getUint16(at + 10, true);
    const packed = bytes.getUint32(at + 20, true);
    const nameLength = bytes.getUint16(at + 28, true), extra = bytes.getUint16(at + 30, true);
    const comment = bytes.getUint16(at + 32, true), local = bytes.getUint32(at + 42, true);
    const path = new TextDecoder().decode(new Uint8Array(bytes.buffer, at + 46, nameLength));
    at += 46 + nameLength + extra + comment;
    if (path.endsWith("/")) continue;
    if (local + 30 > bytes.byteLength || bytes.getUint32(local, true) !== LOCAL_HEADER) {
      throw new Error(`${name}[${path}]: no member where the directory says`);
    }
    const start = local + 30 + bytes.getUint16(local + 26, true) + bytes.getUint16(local + 28, true);
    if (start + packed > bytes.byteLength) throw new Error(`${name}[${path}]: runs past the end of the file`);
    const data = blob.slice(start, start + packed);
    if (method === STORED) members.push({ path, blob: data });
    else if (method === DEFLATED) members.push({ path, blob: await inflate(data) });
    else throw new Error(`${name}[${path}]: compression method ${method} is not read here`);
  }
  return members;
}

function findEnd(bytes, name) {
  // the end record is the last 22 bytes, or fewer than 64 KiB before them with a comment
  for (let at = bytes.byteLength - 22; at >= Math.max(0, bytes.byteLength - 22 - 0xffff); at--) {
    if (bytes.getUint32(at, true) === END_OF_DIRECTORY) return at;
  }
  throw new Error(`${name} is not a zip archive (no end of directory record)`);
}

async function inflate(blob) {
  return new Response(blob.stream().pipeThrough(new DecompressionStream("deflate-raw"))).blob();
}
