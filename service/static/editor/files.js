// Files dropped on the page (images, a folder, the members of a .zip or .usdz) and how a
// document's file reference finds one: the longest tail of its path that some dropped file ends
// with, so `../../../Images/wood.png` finds `Images/wood.png` in a dropped folder and `wood.png`
// alone. A package member `scene.usdz[textures/wood.png]` is looked up by its member path.

import { unzip } from "./zip.js";

const ARCHIVES = /\.(zip|usdz)$/i;

export class DroppedFiles {
  constructor() {
    this.byPath = new Map();  // normalized path -> Blob
    this.version = 0;         // changes with every drop: textures found before are looked up again
  }

  // Add dropped entries ({ path, blob }); archives are opened and their members added under
  // their own paths. Returns the entries added, archives' members included.
  async add(entries) {
    const added = [];
    for (const { path, blob } of entries) {
      const members = ARCHIVES.test(path) ? await unzip(blob, path) : [];
      for (const entry of [{ path, blob }, ...members]) {
        this.byPath.set(normalize(entry.path), entry.blob);
        added.push(entry);
      }
    }
    this.version += 1;
    return added;
  }

  find(reference) {
    const member = /^(.*)\[([^\]]+)\]$/.exec(reference);
    const parts = normalize(member ? member[2] : reference).split("/");
    for (let start = 0; start < parts.length; start++) {
      const tail = parts.slice(start).join("/");
      if (this.byPath.has(tail)) return { path: tail, blob: this.byPath.get(tail) };
      for (const [path, blob] of this.byPath) if (path.endsWith("/" + tail)) return { path, blob };
    }
    return null;
  }
}

// Forward slashes, no leading `./`, `/` or `..` segments (a reference's climb out of its
// document's folder says nothing about where the dropped copy is).
export function normalize(path) {
  return path.replace(/\\/g, "/").split("/").filter((part) => part && part !== "." && part !== "..").join("/");
}

// The files of a drop, folders walked (Chromium's entries API); [{ path, blob }].
export async function droppedEntries(dataTransfer) {
  const items = [...dataTransfer.items].filter((item) => item.kind === "file");
  const entries = items.map((item) => item.webkitGetAsEntry?.()).filter(Boolean);
  if (entries.length !== items.length) {
    return [...dataTransfer.files].map((file) => ({ path: file.webkitRelativePath || file.name, blob: file }));
  }
  const found = [];
  for (const entry of entries) await walk(entry, found);
  return found;
}

async function walk(entry, found) {
  if (entry.isFile) {
    const file = await new Promise((resolve, reject) => entry.file(resolve, reject));
    found.push({ path: entry.fullPath.replace(/^\//, ""), blob: file });
    return;
  }
  const reader = entry.createReader();
  for (;;) {
    const batch = await new Promise((resolve, reject) => reader.readEntries(resolve, reject));
    if (batch.length === 0) return;
    for (const child of batch) await walk(child, found);
  }
}
