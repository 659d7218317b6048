// Edits of a scope's graph (graph.js), written into the XML. Each returns null when done, or
// the reason it is refused (a type mismatch, a cycle), which the view shows where it happened.

import { GRAPH_INPUTS, GRAPH_OUTPUTS, childNamed, readScope, scopeElement } from "./graph.js";

// Connect output `from` ({ box, port }) to input `to` ({ box, port }).
export function connect(xml, scope, library, from, to) {
  const { boxes } = readScope(xml, scope, library);
  const source = boxes.find((box) => box.id === from.box), target = boxes.find((box) => box.id === to.box);
  const output = source?.outputs.find((p) => p.name === from.port), input = target?.inputs.find((p) => p.name === to.port);
  if (!output || !input) return "there is no such port";
  if (output.type !== input.type) {
    return `${from.box}.${from.port} gives ${output.type}; ${to.box}.${to.port} takes ${input.type}`;
  }
  if (from.box === to.box || upstream(boxes, from.box).has(to.box)) {
    return `${to.box} already feeds ${from.box}: the wire would make a cycle`;
  }
  const element = input.element ?? addInput(xml, target.element, input.name, input.type);
  clearConnection(element);
  element.removeAttribute("value");
  if (from.box === GRAPH_INPUTS) element.setAttribute("interfacename", from.port);
  else {
    element.setAttribute(source.kind === "nodegraph" ? "nodegraph" : "nodename", from.box);
    if (source.kind === "nodegraph" || source.outputs.length > 1) element.setAttribute("output", from.port);
  }
  return null;
}

// Take the wire into input `to` away: the input goes back to its definition's default.
export function disconnect(xml, scope, library, to) {
  const { boxes } = readScope(xml, scope, library);
  const input = boxes.find((box) => box.id === to.box)?.inputs.find((p) => p.name === to.port);
  if (!input?.connected) return "that input has no wire";
  clearConnection(input.element);
  if (to.box === GRAPH_OUTPUTS) return null;  // an output without a source is still an output
  const defaultValue = boxes.find((box) => box.id === to.box).definition?.inputs.find((p) => p.name === to.port)?.value;
  if (defaultValue === undefined || defaultValue === null) input.element.remove();
  else input.element.setAttribute("value", defaultValue);
  return null;
}

// Delete a node (or a nodegraph at the top), and every wire it feeds.
export function deleteBox(xml, scope, library, id) {
  if (id === GRAPH_INPUTS || id === GRAPH_OUTPUTS) return "the graph's own inputs and outputs are deleted with the graph";
  const { boxes, wires } = readScope(xml, scope, library);
  const box = boxes.find((b) => b.id === id);
  if (!box) return `there is no ${id} here`;
  for (const wire of wires.filter((w) => w.from.box === id)) disconnect(xml, scope, library, wire.to);
  box.element.remove();
  return null;
}

// A node of a definition, named after its node category: returns its name.
export function addNode(xml, scope, nodedef) {
  const root = scopeElement(xml, scope);
  let index = 1;
  while (childNamed(root, `${nodedef.node}${index}`)) index++;
  const element = xml.createElement(nodedef.node);
  element.setAttribute("name", `${nodedef.node}${index}`);
  element.setAttribute("type", nodedef.outputs.length === 1 ? nodedef.outputs[0].type : "multioutput");
  const material = [...root.children].find((child) => child.getAttribute("type") === "material");
  root.insertBefore(element, material ?? null);  // before the materials, as documents are written
  return element.getAttribute("name");
}

// Names of the boxes upstream of `id` (what it reads from, transitively).
function upstream(boxes, id) {
  const byId = new Map(boxes.map((box) => [box.id, box]));
  const seen = new Set(), todo = [id];
  while (todo.length) {
    for (const input of byId.get(todo.pop())?.inputs ?? []) {
      const from = input.element && (input.element.getAttribute("nodename") || input.element.getAttribute("nodegraph")
                                     || (input.element.hasAttribute("interfacename") ? GRAPH_INPUTS : null));
      if (from && !seen.has(from)) {
        seen.add(from);
        todo.push(from);
      }
    }
  }
  return seen;
}

function addInput(xml, element, name, type) {
  const input = xml.createElement("input");
  input.setAttribute("name", name);
  input.setAttribute("type", type);
  element.appendChild(input);
  return input;
}

function clearConnection(element) {
  for (const attribute of ["nodename", "nodegraph", "output", "interfacename"]) element.removeAttribute(attribute);
}
