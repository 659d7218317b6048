// The editor page: a document in, the server's record out (controls, graph, preview, source,
// passes, or the error where it belongs). A value edit (a control, a value in the graph's
// inspector) goes to the GPU and into the document text; a topology edit (edits.js), Generate,
// or a new document, material or interface asks the server again.

import { exampleDocument, generate, generateUsd, nodedefs, traffic } from "./api.js";
import { buildControls } from "./controls.js";
import { materials, parseDocument } from "./documents.js";
import { acceptDrops } from "./drops.js";
import { Edits } from "./edits.js";
import { installExports } from "./exports.js";
import { DroppedFiles, normalize } from "./files.js";
import { GraphEditor } from "./grapheditor.js";
import { Library } from "./library.js";
import { Preview } from "./preview.js";
import { installScene } from "./scene.js";
import { documentFromFragment } from "./share.js";
import { textureRequests } from "./textures.js";

const $ = (id) => document.getElementById(id);
const page = {
  document: $("document"), error: $("error"), status: $("status"), material: $("material"),
  interface: $("interface"), live: $("live"), controls: $("controls"), output: $("output"),
  note: $("preview-note"), canvas: $("preview"), textures: $("textures"),
};
// `usd`: a dropped USD layer or usdz generated as it is ({ blob, media, name }), instead of the text
const state = { record: null, tab: "pixel", preview: null, xml: null, files: new DroppedFiles(), usd: null, name: "material" };

// for the browser tests and for anyone curious in the console
window.shaderxEditor = { state, traffic, ready: false, runs: 0 };  // runs: records shown (or failed)
state.edits = new Edits({ state, textarea: page.document, run: () => run(), refresh: () => refresh() });
window.shaderxEditor.timings = state.edits.timings;

async function start() {
  try {
    state.preview = await Preview.create(page.canvas, state.files);
    if (!state.preview) page.note.textContent = "This browser has no WebGL2: listings only.";
  } catch (failure) {
    page.note.textContent = `No live preview: ${failure.message}`;
  }
  window.shaderxEditor.preview = state.preview;
  const definitions = await nodedefs();
  if (definitions.error) page.note.textContent = `No node palette: ${definitions.error.message}`;
  state.graph = new GraphEditor({ canvas: $("graph"), crumbs: $("graph-crumbs"), inspector: $("inspector"),
                                  search: $("palette-search"), palette: $("palette"), note: $("graph-note") },
                                new Library(definitions.error ? [] : definitions),
                                { xml: () => state.xml, topology: (mutate) => state.edits.topology(mutate),
                                  value: (path, type, text) => state.edits.value(path, type, text) });
  window.shaderxEditor.graph = state.graph;
  $("undo").addEventListener("click", () => state.edits.undo());
  $("redo").addEventListener("click", () => state.edits.redo());
  window.addEventListener("keydown", (event) => {
    if (!(event.ctrlKey || event.metaKey) || event.target.closest?.("input, textarea")) return;
    const key = event.key.toLowerCase();
    if (key === "z" && !event.shiftKey) state.edits.undo();
    else if (key === "y" || (key === "z" && event.shiftKey)) state.edits.redo();
    else return;
    event.preventDefault();
  });
  page.live.checked = state.preview !== null;
  page.live.disabled = state.preview === null;
  $("example").addEventListener("change", (event) => event.target.value && loadExample(event.target.value));
  $("upload").addEventListener("change", async (event) => {
    const file = event.target.files[0];
    if (file) await openDocument(await file.text());
  });
  const report = (code) => (failure) => showError({ error: { code, message: failure.message || String(failure), where: null } });
  const sceneFiles = state.preview
    ? installScene({ mesh: $("mesh"), environment: $("environment"), intensity: $("intensity"), rotation: $("rotation"),
                     turntable: $("turntable") }, state.preview, report("invalid_scene_file"))
    : async () => report("invalid_scene_file")(new Error("no WebGL2 preview to draw a scene in"));
  acceptDrops(document.body, state.files, {
    sceneFiles,
    open: (dropped) => (dropped.usd ? openUsd(dropped.usd) : openDocument(dropped.text, dropped.name)),
    texturesChanged: async () => {
      if (state.preview && state.record?.stages?.pixel) await state.preview.reloadTextures(state.record);
      showTextures();
    },
    failed: report("invalid_drop"),
    isTexture: (path) => state.record !== null && textureRequests(state.record)
      .some((request) => normalize(request.file).split("/").pop() === normalize(path).split("/").pop()),
  });
  $("generate").addEventListener("click", () => run());
  page.material.addEventListener("change", () => run());
  page.interface.addEventListener("change", () => run());
  page.live.addEventListener("change", () => run());
  for (const button of document.querySelectorAll("#output-pane nav button")) {
    button.addEventListener("click", () => showTab(button.dataset.tab));
  }
  for (const button of document.querySelectorAll("#document-pane nav button")) {
    button.addEventListener("click", () => showDocumentView(button.dataset.view));
  }
  window.shaderxEditor.exports = installExports(
    { mtlx: $("save-mtlx"), usda: $("save-usda"), png: $("save-png"), link: $("share"), linkField: $("link") },
    { text: () => page.document.value, xml: () => state.xml, library: () => state.graph.library, canvas: page.canvas,
      name: () => state.name },
    (failure) => showError({ error: { code: "export_failed", message: failure.message, where: null } }));
  const linked = await documentFromFragment(location.hash).catch((failure) => {
    showError({ error: { code: "invalid_link", message: `the link's document cannot be read: ${failure.message}`, where: "#doc" } });
    return null;
  });
  const drawn = linked !== null ? await openDocument(linked, "linked.mtlx") : await loadExample("gold.mtlx");
  if (drawn) {  // the time from the page's navigation to its first frame (bench/editor.py reads it)
    await state.preview.nextFrame();
    window.shaderxEditor.firstFrameMs = performance.now();
  }
  window.shaderxEditor.ready = true;
}

async function loadExample(name) {
  $("example").value = name;
  return openDocument(await exampleDocument(name), name);
}

async function openDocument(text, name = "material.mtlx") {
  state.usd = null;
  state.name = baseName(name);
  page.document.readOnly = false;
  page.document.value = text;
  return run();
}

async function openUsd(usd) {
  state.usd = usd;
  state.name = baseName(usd.name);
  page.document.readOnly = true;
  page.document.value = usd.media === "model/vnd.usda" ? await usd.blob.text()
    : `${usd.name}: a usdz package, generated as it is (its layers are not edited here)`;
  await run();
}

const baseName = (path) => path.replace(/^.*[\\/]/, "").replace(/\.[^.]*$/, "") || "material";

// The material menu follows the document text, keeping the choice while it still exists.
function refreshMaterials() {
  const names = materials(state.xml), chosen = page.material.value;
  page.material.replaceChildren(...names.map((name) => new Option(name, name)));
  if (names.includes(chosen)) page.material.value = chosen;
}

// Ask the server for the record of the chosen material. Without a live preview only the
// listing is needed, so the source is not requested.
async function run() {
  const text = page.document.value;
  state.xml = state.usd ? null : parseDocument(text);
  refreshMaterials();
  const source = page.live.checked && state.preview !== null;
  page.status.textContent = "generating…";
  const options = { element: page.material.value || null, interface: page.interface.value, source };
  const record = state.usd ? await generateUsd(state.usd.blob, state.usd.media, options) : await generate(text, options);
  page.status.textContent = `${traffic.generate} requests`;
  state.graph?.show();
  if (record.error) {
    showError(record);
    window.shaderxEditor.runs += 1;
    return false;
  }
  page.error.hidden = true;
  state.record = record;
  const uniforms = record.blocks.pixel?.PublicUniforms ?? [];
  const sections = buildControls(page.controls, uniforms, (...change) => state.edits.control(...change));
  page.status.textContent = `${record.element}: ${uniforms.length} public uniforms in ${sections} sections` +
    `${record.cached ? " (cached)" : ""}; ${traffic.generate} requests`;
  if (source) await showPreview(record);
  else page.note.textContent = state.preview ? "Live preview off: listings only (source: false)." : page.note.textContent;
  showTextures();
  showTab(state.tab);
  window.shaderxEditor.runs += 1;
  return source;
}

// After a value edit: the controls show the values, the graph the document.
function refresh() {
  if (state.record) buildControls(page.controls, state.record.blocks.pixel?.PublicUniforms ?? [], (...change) => state.edits.control(...change));
  state.graph?.show();
}

function showDocumentView(view) {
  for (const button of document.querySelectorAll("#document-pane nav button")) button.classList.toggle("active", button.dataset.view === view);
  $("graph-view").hidden = view !== "graph";
  page.document.hidden = view !== "text";
}

async function showPreview(record) {
  try {
    const compiles = state.preview.stats.compiles;
    await state.preview.show(record);
    page.note.textContent = state.preview.stats.compiles > compiles ? "compiled" : "same source: no recompile";
  } catch (failure) {
    showError({ element: record.element, error: { code: "webgl_compile", message: failure.message, where: record.element } });
  }
}

// Each file texture of the record shown: where it came from, or why its default colour is drawn.
function showTextures() {
  const files = state.preview ? [...state.preview.files.values()] : [];
  page.textures.replaceChildren(...files.map(({ request, from, problem }) => {
    const item = document.createElement("li");
    item.dataset.sampler = request.name;
    item.className = problem ? "missing" : "loaded";
    item.textContent = problem ? `${request.file}: default colour (${problem})` : `${request.file} (${from})`;
    return item;
  }));
}

function showError(record) {
  const { code, message, where } = record.error;
  page.error.replaceChildren();
  const title = document.createElement("strong");
  title.textContent = code;
  const place = document.createElement("code");
  place.textContent = where ?? "";
  page.error.append(title, where ? " at " : "", place, `\n${message}`);
  page.error.hidden = false;
  page.status.textContent = `error: ${code}; ${traffic.generate} requests`;
}

function showTab(tab) {
  state.tab = tab;
  for (const button of document.querySelectorAll("#output-pane nav button")) button.classList.toggle("active", button.dataset.tab === tab);
  const record = state.record;
  if (!record) return void (page.output.textContent = "");
  if (tab === "passes") page.output.textContent = passesReport(record.passes);
  else if (tab === "record") page.output.textContent = JSON.stringify({ ...record, stages: undefined }, null, 2);
  else page.output.textContent = record.stages?.[tab] ?? "(source not requested: live preview is off)";
}

// The passes' report as a table of rows, whatever its exact shape: a list of objects or a map
// from pass name to edits.
function passesReport(passes) {
  if (!passes) return "This record has no passes report.";
  const rows = Array.isArray(passes) ? passes : Object.entries(passes).map(([name, value]) => ({ name, ...(typeof value === "object" ? value : { edits: value }) }));
  const keys = [...new Set(rows.flatMap((row) => Object.keys(row)))];
  const cell = (value) => (typeof value === "object" ? JSON.stringify(value) : String(value ?? ""));
  const widths = keys.map((key) => Math.max(key.length, ...rows.map((row) => cell(row[key]).length)));
  const line = (values) => values.map((value, i) => value.padEnd(widths[i])).join("  ");
  return [line(keys), line(widths.map((w) => "-".repeat(w))), ...rows.map((row) => line(keys.map((key) => cell(row[key]))))].join("\n");
}

start();
