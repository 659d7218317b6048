// Field USDZ for bench/usd_field.py (issue 21): three.js's own USDZExporter (the npm package
// `three`, MIT), which web apps use to hand a scene to AR viewers, run on spheres with the material
// set-ups such apps export. Textures are 8 x 8 PNGs made here; the canvas the exporter draws them
// into is a stand-in that returns those bytes (node has no DOM).
//
//   mkdir /tmp/three && cd /tmp/three && npm install three@0.187.0
//   cp .../bench/usd_field_three.mjs . && node usd_field_three.mjs /tmp/field/three.usdz
//   .venv/bin/python bench/usd_field.py /tmp/field
import fs from 'node:fs';
import zlib from 'node:zlib';
import * as THREE from 'three';
import { USDZExporter } from 'three/addons/exporters/USDZExporter.js';

function png(pixel) {  // an 8 x 8 RGB PNG of pixel(x, y) -> [r, g, b] bytes
  const crcTable = Array.from({ length: 256 }, (_, n) => { let c = n; for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1; return c >>> 0; });
  const crc = (bytes) => { let c = 0xffffffff; for (const b of bytes) c = crcTable[(c ^ b) & 255] ^ (c >>> 8); return (c ^ 0xffffffff) >>> 0; };
  const chunk = (kind, data) => {
    const body = Buffer.concat([Buffer.from(kind), data]);
    const out = Buffer.alloc(body.length + 8); out.writeUInt32BE(data.length, 0); body.copy(out, 4); out.writeUInt32BE(crc(body), body.length + 4);
    return out;
  };
  const rows = []; for (let y = 0; y < 8; y++) { rows.push(0); for (let x = 0; x < 8; x++) rows.push(...pixel(x, y)); }
  const header = Buffer.alloc(13); header.writeUInt32BE(8, 0); header.writeUInt32BE(8, 4); header[8] = 8; header[9] = 2;
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', header),
    chunk('IDAT', zlib.deflateSync(Buffer.from(rows))), chunk('IEND', Buffer.alloc(0))]);
}
const IMAGES = {
  color: png((x, y) => (x < 4) === (y < 4) ? [230, 60, 30] : [40, 160, 230]),
  normal: png(() => [128, 128, 255]),
  grey: png(() => [186, 186, 186]),
};

globalThis.ImageBitmap = class ImageBitmap { constructor(file) { this.file = file; this.width = 8; this.height = 8; } };
let current = null;
globalThis.document = { createElement: () => ({
  getContext: () => ({ translate() {}, scale() {}, drawImage(image) { current = image.file; } }),
  toBlob: (resolve) => { const bytes = IMAGES[current]; resolve({ arrayBuffer: async () => bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length) }); },
}) };
const texture = (file, colorSpace = THREE.NoColorSpace) => {
  const t = new THREE.Texture(new ImageBitmap(file)); t.colorSpace = colorSpace; t.wrapS = t.wrapT = THREE.RepeatWrapping; return t;
};
const srgb = (file) => texture(file, THREE.SRGBColorSpace);

const materials = {
  plain: new THREE.MeshStandardMaterial({ color: 0x3366cc, roughness: 0.4, metalness: 0.1 }),
  textured: new THREE.MeshStandardMaterial({ map: srgb('color'), normalMap: texture('normal'), roughnessMap: texture('grey'), metalnessMap: texture('grey'), aoMap: texture('grey') }),
  transformed: (() => { const t = srgb('color'); t.repeat.set(3, 2); t.offset.set(0.25, 0); t.rotation = 0.3; return new THREE.MeshStandardMaterial({ map: t }); })(),
  transparent: new THREE.MeshStandardMaterial({ map: srgb('color'), transparent: true, opacity: 0.6 }),
  cutout: new THREE.MeshStandardMaterial({ map: srgb('color'), alphaTest: 0.5 }),
  alpha_map: new THREE.MeshStandardMaterial({ color: 0x22aa44, alphaMap: texture('grey') }),
  emissive: new THREE.MeshStandardMaterial({ color: 0x111111, emissive: 0xff8800, emissiveIntensity: 2 }),
  emissive_map: new THREE.MeshStandardMaterial({ emissive: 0xffffff, emissiveMap: srgb('color') }),
  glass: new THREE.MeshPhysicalMaterial({ color: 0xffffff, roughness: 0.05, transparent: true, opacity: 0.1, ior: 1.5 }),
  clearcoat: new THREE.MeshPhysicalMaterial({ color: 0xaa1111, clearcoat: 1, clearcoatRoughness: 0.05, roughness: 0.5 }),
  clearcoat_maps: new THREE.MeshPhysicalMaterial({ color: 0x1111aa, clearcoat: 0.8, clearcoatMap: texture('grey'), clearcoatRoughnessMap: texture('grey') }),
  normal_scaled: (() => { const m = new THREE.MeshStandardMaterial({ normalMap: texture('normal') }); m.normalScale.set(0.4, 0.4); return m; })(),
};
const scene = new THREE.Scene();
let x = 0;
for (const [name, material] of Object.entries(materials)) {
  const mesh = new THREE.Mesh(new THREE.SphereGeometry(0.5, 8, 6), material);
  mesh.name = name; mesh.position.x = x++; scene.add(mesh);
}
const bytes = await new USDZExporter().parseAsync(scene);
fs.writeFileSync(process.argv[2], Buffer.from(bytes));
console.log(`wrote ${process.argv[2]}: ${Object.keys(materials).length} materials`);
