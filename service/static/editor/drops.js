// Drops on the page: images, a folder, a .zip or a .usdz. Every file joins the page's dropped
// files (files.js), which document references are resolved against; a MaterialX document among
// them (a dropped one, or one inside the archive) is opened, else a USD layer or usdz package is
// generated as it is (a package's textures being its own members).

import { droppedEntries } from "./files.js";
import { SCENE_FILE } from "./scene.js";

const DOCUMENT = /\.(mtlx|xml)$/i;
const MESH = /\.obj$/i;
const USD = [[/\.usdz$/i, "model/vnd.usdz+zip"], [/\.usda$/i, "model/vnd.usda"]];

// `open({ text, name } | { usd: { blob, media, name } })` for a document; `sceneFiles(entries)` for
// meshes and environments (scene.js); `texturesChanged()` otherwise. A dropped .hdr or .exr is an
// environment unless the drop holds a document or `isTexture(path)` says the open document names
// it: then it is a texture like any other image.
export function acceptDrops(target, files, { open, sceneFiles, texturesChanged, failed, isTexture = () => false }) {
  target.addEventListener("dragover", (event) => {
    event.preventDefault();
    event.dataTransfer.dropEffect = "copy";
  });
  target.addEventListener("drop", async (event) => {
    event.preventDefault();
    try {
      const everything = await droppedEntries(event.dataTransfer);
      const withDocument = everything.some((entry) => DOCUMENT.test(entry.path) || USD.some(([pattern]) => pattern.test(entry.path)));
      const isScene = (entry) => MESH.test(entry.path)
        || (SCENE_FILE.test(entry.path) && !withDocument && !isTexture(entry.path));
      const scene = everything.filter(isScene);
      if (scene.length) await sceneFiles(scene);
      const dropped = everything.filter((entry) => !isScene(entry));
      if (!dropped.length) return;
      const added = await files.add(dropped);
      const document = added.find((entry) => DOCUMENT.test(entry.path));
      const usd = dropped.map((entry) => ({ entry, media: USD.find(([pattern]) => pattern.test(entry.path))?.[1] }))
        .find(({ media }) => media);
      if (document) await open({ text: await document.blob.text(), name: document.path });
      else if (usd) await open({ usd: { blob: usd.entry.blob, media: usd.media, name: usd.entry.path } });
      else await texturesChanged(added.map((entry) => entry.path));
    } catch (failure) {
      failed(failure);
    }
  });
}
