// What the editor reads from a document itself: the materials for the menu, and edited values
// written back into the XML, so that the next request generates what the controls show.
// Everything else (resolution, validation, errors) is the server's job.

const MATERIAL_TYPE = "material";

export function parseDocument(text) {
  const xml = new DOMParser().parseFromString(text, "application/xml");
  return xml.querySelector("parsererror") ? null : xml;
}

// Name paths of the top-level material nodes, in document order; empty when there are none
// (the server then picks the first renderable element itself).
export function materials(xml) {
  if (!xml) return [];
  return [...xml.documentElement.children]
    .filter((child) => child.getAttribute("type") === MATERIAL_TYPE && child.getAttribute("name"))
    .map((child) => child.getAttribute("name"));
}

// The text of a listing value as MaterialX writes it: "0.1, 0.2, 0.3", "true", "4".
export function valueString(value) {
  if (Array.isArray(value)) return value.map(valueString).join(", ");
  if (typeof value === "number") return Number.isInteger(value) ? String(value) : String(+value.toPrecision(7));
  return String(value);
}

// Set the input at `path` (graph/node/input) to `text`, adding the input to its node when the
// node exists but leaves the input at its default. Returns false when the path names nothing
// in this document (an input of a library nodedef, for instance).
export function setInputValue(xml, path, type, text) {
  const names = path.split("/");
  let element = xml.documentElement;
  for (const name of names.slice(0, -1)) {
    element = [...element.children].find((child) => child.getAttribute("name") === name);
    if (!element) return false;
  }
  const inputName = names[names.length - 1];
  let input = [...element.children].find((child) => child.localName === "input" && child.getAttribute("name") === inputName);
  if (!input) {
    if (element.localName === "nodegraph" || element.localName === "nodedef") return false;
    input = xml.createElement("input");
    input.setAttribute("name", inputName);
    input.setAttribute("type", type);
    element.appendChild(input);
  }
  if (input.hasAttribute("nodename") || input.hasAttribute("nodegraph") || input.hasAttribute("interfacename")) return false;
  input.setAttribute("value", text);
  return true;
}

export function serialize(xml) {
  return new XMLSerializer().serializeToString(xml);
}
