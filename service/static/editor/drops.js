// Drops on the page: images, a folder, a .zip or a .usdz. Every file joins the page's dropped
// files (files.js), which document references are resolved against; a MaterialX document among
// them (a dropped one, or one inside the archive) is opened, else a usdz package is generated as
// it is (its textures being its own members).

import { droppedEntries } from "./files.js";

const DOCUMENT = /\.(mtlx|xml)$/i, PACKAGE = /\.usdz$/i;

// `open({ text, name } | { package: blob, name })` for a document; `texturesChanged()` otherwise.
export function acceptDrops(target, files, { open, texturesChanged, failed }) {
  target.addEventListener("dragover", (event) => {
    event.preventDefault();
    event.dataTransfer.dropEffect = "copy";
  });
  target.addEventListener("drop", async (event) => {
    event.preventDefault();
    try {
      const dropped = await droppedEntries(event.dataTransfer);
      const added = await files.add(dropped);
      const document = added.find((entry) => DOCUMENT.test(entry.path));
      const pack = dropped.find((entry) => PACKAGE.test(entry.path));
      if (document) await open({ text: await document.blob.text(), name: document.path });
      else if (pack) await open({ package: pack.blob, name: pack.path });
      else await texturesChanged(added.map((entry) => entry.path));
    } catch (failure) {
      failed(failure);
    }
  });
}
