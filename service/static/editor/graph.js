// One scope of a MaterialX document (the document itself, or a nodegraph in it) read as boxes
// with typed ports and the wires between them. Read from the XML every time it is drawn: the
// document is the one truth, and graphedits.js writes every change into it.
//
// Boxes: the scope's nodes; at the top, its nodegraphs too (their outputs are ports, double-click
// enters them); inside a nodegraph, "(inputs)" holds its interface inputs as outputs and
// "(outputs)" its outputs as inputs, so every wire joins an output port to an input port.

export const GRAPH_INPUTS = "(inputs)", GRAPH_OUTPUTS = "(outputs)";
const NOT_NODES = new Set(["nodedef", "typedef", "implementation", "look", "lookgroup", "materialassign", "collection",
  "geominfo", "propertyset", "variantset", "unitdef", "unittypedef", "attributedef", "targetdef", "backdrop",
  "input", "output", "token", "member", "colorspace"]);

// The element of a scope path ("" is the document, "NG" a nodegraph, "NG/inner" one inside it).
export function scopeElement(xml, scope) {
  let element = xml.documentElement;
  for (const name of scope ? scope.split("/") : []) {
    element = childNamed(element, name);
    if (!element) return null;
  }
  return element;
}

export const childNamed = (element, name, localName = null) => [...element.children].find((child) =>
  child.getAttribute("name") === name && (localName === null || child.localName === localName)) ?? null;

export function readScope(xml, scope, library) {
  const root = scopeElement(xml, scope);
  const boxes = [], wires = [];
  if (!root) return { boxes, wires };
  const inGraph = root.localName === "nodegraph";
  for (const element of root.children) {
    if (element.localName === "nodegraph" && !inGraph) boxes.push(graphBox(element, library));
    else if (!NOT_NODES.has(element.localName) && element.localName !== "nodegraph") boxes.push(nodeBox(element, library));
  }
  const interfaceInputs = inGraph ? inputsOf(root, library.definition(root)) : [];
  if (interfaceInputs.length) boxes.unshift({ id: GRAPH_INPUTS, kind: GRAPH_INPUTS, label: "graph inputs", inputs: [], outputs: interfaceInputs.map(({ name, type }) => ({ name, type })) });
  const outputs = [...root.children].filter((child) => child.localName === "output");
  if (outputs.length) {
    boxes.push({ id: GRAPH_OUTPUTS, kind: GRAPH_OUTPUTS, label: inGraph ? "graph outputs" : "outputs", element: root, outputs: [],
                 inputs: outputs.map((output) => port(output, null)) });
  }
  const ids = new Set(boxes.map((box) => box.id));
  for (const box of boxes) {
    for (const input of box.inputs) {
      const from = source(input.element);
      if (from && ids.has(from.box)) wires.push({ from, to: { box: box.id, port: input.name } });
    }
  }
  for (const wire of wires) wire.from.port ??= boxes.find((box) => box.id === wire.from.box).outputs[0]?.name;
  return { boxes, wires, inGraph };
}

function nodeBox(element, library) {
  const definition = library.definition(element);
  const name = element.getAttribute("name");
  const outputs = definition ? definition.outputs.map(({ name: n, type }) => ({ name: n, type }))
                             : [{ name: "out", type: element.getAttribute("type") }];
  return { id: name, kind: "node", label: name, category: element.localName, type: element.getAttribute("type"),
           element, definition, inputs: inputsOf(element, definition), outputs };
}

function graphBox(element, library) {
  const outputs = [...element.children].filter((child) => child.localName === "output")
    .map((output) => ({ name: output.getAttribute("name"), type: output.getAttribute("type") }));
  const definition = library.definition(element);
  return { id: element.getAttribute("name"), kind: "nodegraph", label: element.getAttribute("name"), category: "nodegraph",
           element, definition, inputs: inputsOf(element, definition), outputs };
}

// An element's input ports: every input of its definition (the element's own, if any, holding
// its value or connection), then inputs the element has that the definition lacks.
function inputsOf(element, definition) {
  const own = [...element.children].filter((child) => child.localName === "input");
  const ports = (definition?.inputs ?? []).map((input) => port(own.find((e) => e.getAttribute("name") === input.name) ?? null, input));
  for (const input of own) if (!ports.some((p) => p.name === input.getAttribute("name"))) ports.push(port(input, null));
  return ports;
}

function port(element, definition) {
  return { name: element?.getAttribute("name") ?? definition.name, type: element?.getAttribute("type") ?? definition.type,
           element, value: element?.getAttribute("value") ?? definition?.value ?? null, present: element !== null,
           connected: element !== null && source(element) !== null };
}

// What an input (or output) element reads from: { box, port } or null for a value.
export function source(element) {
  if (!element) return null;
  const output = element.getAttribute("output") || null;
  if (element.hasAttribute("nodename")) return { box: element.getAttribute("nodename"), port: output };
  if (element.hasAttribute("nodegraph")) return { box: element.getAttribute("nodegraph"), port: output };
  if (element.hasAttribute("interfacename")) return { box: GRAPH_INPUTS, port: element.getAttribute("interfacename") };
  return null;
}
