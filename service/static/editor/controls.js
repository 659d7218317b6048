// Controls for a record's public uniforms, drawn from each listing's `ui` hints: sliders over the
// soft range, colour pickers, menus for enums, check boxes, one section per folder.
// A control reports (variable, value for the uniform, value text for the document, document type).

import { valueString } from "./documents.js";

const VECTOR_SIZES = { vector2: 2, vector3: 3, vector4: 4 };
const SLIDER_STEPS = 1000;

export function buildControls(container, variables, onChange) {
  container.replaceChildren();
  const sections = new Map();
  for (const variable of variables) {
    const control = controlFor(variable, (value, text = valueString(value), type = variable.type) =>
      onChange(variable, value, text, type));
    if (!control) continue;
    const folder = variable.ui?.folder ?? parentPath(variable.path) ?? "Inputs";
    if (!sections.has(folder)) {
      const details = document.createElement("details");
      details.open = true;
      const summary = document.createElement("summary");
      summary.textContent = folder;
      details.append(summary);
      sections.set(folder, details);
    }
    sections.get(folder).append(row(variable, control));
  }
  for (const section of sections.values()) {
    // advanced inputs last, as MaterialX's tools show them
    const advanced = [...section.querySelectorAll(".control.advanced")];
    section.append(...advanced);
    container.append(section);
  }
  return sections.size;
}

function controlFor(variable, report) {
  const ui = variable.ui ?? {};
  if (ui.enum) return enumMenu(variable, ui, report);
  if (variable.type === "float" || variable.type === "integer") return slider(variable, ui, report);
  if (variable.type === "boolean") return checkbox(variable, report);
  if (variable.type === "color3" || variable.type === "color4") return colourPicker(variable, report);
  if (variable.type in VECTOR_SIZES) return vectorFields(variable, report);
  return null;  // strings, file names, matrices and closures have no control here
}

function row(variable, control) {
  const div = document.createElement("div");
  div.className = "control" + (variable.ui?.advanced ? " advanced" : "");
  div.dataset.uniform = variable.name;
  div.dataset.path = variable.path ?? "";  // the element it edits: uniform names come from the graph's structure
  const label = document.createElement("label");
  label.textContent = variable.ui?.name ?? lastName(variable.path) ?? variable.name;
  label.title = [variable.path, variable.ui?.doc].filter(Boolean).join("\n");
  const value = document.createElement("div");
  value.className = "value";
  value.append(...control);
  div.append(label, value);
  return div;
}

function slider(variable, ui, report) {
  const integer = variable.type === "integer";
  const value = Number(variable.value ?? 0);
  const [lo, hi] = range(ui, value);
  const step = ui.step ?? (integer ? 1 : (hi - lo) / SLIDER_STEPS);
  const track = input("range", { min: lo, max: hi, step, value });
  const number = input("number", { step: integer ? 1 : "any", value });
  const set = (text, from) => {
    const parsed = integer ? Math.round(Number(text)) : Number(text);
    if (!Number.isFinite(parsed)) return;
    if (from !== track) track.value = parsed;
    if (from !== number) number.value = parsed;
    report(parsed);
  };
  track.addEventListener("input", () => set(track.value, track));
  number.addEventListener("input", () => set(number.value, number));
  return [track, number];
}

// The soft range when the nodedef gives one, else the hard range, else one around the value.
function range(ui, value) {
  const lo = ui.softmin ?? ui.min ?? Math.min(0, value * 2);
  const hi = ui.softmax ?? ui.max ?? Math.max(1, value * 2);
  return [Math.min(lo, value), Math.max(hi, value)];
}

function checkbox(variable, report) {
  const box = input("checkbox");
  box.checked = Boolean(variable.value);
  box.addEventListener("change", () => report(box.checked));
  return [box];
}

function enumMenu(variable, ui, report) {
  const menu = document.createElement("select");
  ui.enum.forEach((name, index) => menu.append(new Option(name, String(index))));
  const values = ui.enumvalues;
  const current = values ? values.findIndex((v) => valueString(v) === valueString(variable.value)) : Number(variable.value);
  menu.value = String(Math.max(0, current));
  menu.addEventListener("change", () => {
    const index = Number(menu.value);
    // a string enum is published as the index of its name: the uniform takes the index, the
    // document the name
    if (values) report(values[index]);
    else report(index, ui.enum[index], "string");
  });
  return [menu];
}

function colourPicker(variable, report) {
  const value = variable.value ?? [0, 0, 0, 1];
  const encoded = !/srgb/i.test(variable.colorspace ?? "");  // linear values are shown sRGB-encoded
  const picker = input("color", { value: toHex(value, encoded) });
  const alpha = variable.type === "color4" ? input("number", { min: 0, max: 1, step: "any", value: value[3] ?? 1 }) : null;
  const send = () => {
    const rgb = fromHex(picker.value, encoded);
    report(alpha ? [...rgb, Number(alpha.value)] : rgb);
  };
  picker.addEventListener("input", send);
  alpha?.addEventListener("input", send);
  return alpha ? [picker, alpha] : [picker];
}

function vectorFields(variable, report) {
  const size = VECTOR_SIZES[variable.type];
  const value = variable.value ?? new Array(size).fill(0);
  const fields = value.slice(0, size).map((component) => input("number", { step: "any", value: component }));
  const send = () => report(fields.map((field) => Number(field.value) || 0));
  fields.forEach((field) => field.addEventListener("input", send));
  return fields;
}

function input(type, attributes = {}) {
  const element = document.createElement("input");
  element.type = type;
  for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, String(value));
  if ("value" in attributes) element.value = String(attributes.value);
  return element;
}

const toHex = (rgb, encoded) => "#" + rgb.slice(0, 3).map((c) => {
  const x = Math.min(1, Math.max(0, encoded ? srgbEncode(c) : c));
  return Math.round(x * 255).toString(16).padStart(2, "0");
}).join("");

const fromHex = (hex, encoded) => [1, 3, 5].map((i) => {
  const x = parseInt(hex.slice(i, i + 2), 16) / 255;
  return +(encoded ? srgbDecode(x) : x).toFixed(5);
});

const srgbEncode = (x) => (x <= 0.0031308 ? x * 12.92 : 1.055 * x ** (1 / 2.4) - 0.055);
const srgbDecode = (x) => (x <= 0.04045 ? x / 12.92 : ((x + 0.055) / 1.055) ** 2.4);
const parentPath = (path) => (path && path.includes("/") ? path.slice(0, path.lastIndexOf("/")) : null);
const lastName = (path) => (path ? path.slice(path.lastIndexOf("/") + 1) : null);
