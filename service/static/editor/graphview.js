// The graph of one scope drawn as SVG: boxes with typed ports (coloured by type), wires as
// curves, laid out by layout.js. Pointer gestures become requests to the page (`actions`):
// select a box or a wire, double-click a nodegraph to enter it, drag from an output port to an
// input port to connect. A refused connection is shown where it was dropped, with its reason.

import { GRAPH_OUTPUTS } from "./graph.js";
import { BOX_WIDTH, PORT, TITLE, layout } from "./layout.js";

const SVG = "http://www.w3.org/2000/svg";
const TITLE_CHARACTERS = 24;  // what fits beside the +N toggle in a box
const TYPE_COLOURS = { float: "#9ecbff", integer: "#7fd1b9", boolean: "#e6a0c4", color3: "#ffcf70", color4: "#ffb347",
  vector2: "#b8e986", vector3: "#8fd694", vector4: "#6fc27a", filename: "#d0a0ff", string: "#c0c0c0",
  surfaceshader: "#ff8a80", material: "#ff5252", displacementshader: "#f48fb1", volumeshader: "#ce93d8",
  BSDF: "#80cbc4", EDF: "#ffe082", VDF: "#b39ddb" };

export class GraphView {
  // actions: { select(selection), enter(boxId), connect(from, to) -> reason | null }
  constructor(container, actions) {
    this.container = container;
    this.actions = actions;
    this.expanded = new Set();  // boxes drawn with every input, not only those set
    this.selection = null;      // { box } or { wire: { box, port } } (the input end)
    this.refusal = null;        // the last refused connection's reason, shown until the next gesture
    this.svg = element("svg", { class: "graph" });
    container.replaceChildren(this.svg);
  }

  inputsShown = (box) => (box.kind !== "node" || this.expanded.has(box.id) ? box.inputs
    : box.inputs.filter((input) => input.present || input.connected));

  draw(graph) {
    this.graph = graph;
    const { places, width, height } = layout(graph, { inputs: this.inputsShown });
    this.places = places;
    this.svg.replaceChildren();
    this.svg.setAttribute("width", width);
    this.svg.setAttribute("height", height);
    for (const wire of graph.wires) this.drawWire(wire);
    for (const box of graph.boxes) this.drawBox(box, places.get(box.id));
    if (this.refusal) this.showRefusal(this.refusal.text, this.refusal.at);
  }

  portPoint(boxId, side, portName) {
    const box = this.graph.boxes.find((b) => b.id === boxId), place = this.places.get(boxId);
    const ports = side === "in" ? this.inputsShown(box) : box.outputs;
    const index = Math.max(0, ports.findIndex((p) => p.name === portName));
    return { x: place.x + (side === "in" ? 0 : BOX_WIDTH), y: place.y + TITLE + index * PORT + PORT / 2 };
  }

  drawWire(wire) {
    const a = this.portPoint(wire.from.box, "out", wire.from.port), b = this.portPoint(wire.to.box, "in", wire.to.port);
    const type = this.graph.boxes.find((box) => box.id === wire.from.box).outputs.find((p) => p.name === wire.from.port)?.type;
    const selected = this.selection?.wire && this.selection.wire.box === wire.to.box && this.selection.wire.port === wire.to.port;
    const path = element("path", { d: curve(a, b), class: "wire" + (selected ? " selected" : ""), stroke: TYPE_COLOURS[type] ?? "#aaa",
                                   "data-to": `${wire.to.box}.${wire.to.port}` });
    path.addEventListener("click", (event) => {
      event.stopPropagation();
      this.select({ wire: wire.to });
    });
    this.svg.append(path);
  }

  drawBox(box, place) {
    const group = element("g", { class: `box ${box.kind}` + (this.selection?.box === box.id ? " selected" : ""),
                                 transform: `translate(${place.x},${place.y})`, "data-box": box.id });
    group.append(element("rect", { width: place.width, height: place.height, rx: 5 }));
    const title = element("text", { x: 8, y: 15, class: "title" });
    const label = box.category && box.category !== box.label ? `${box.label} · ${box.category}` : box.label;
    title.textContent = label.length > TITLE_CHARACTERS ? label.slice(0, TITLE_CHARACTERS - 1) + "…" : label;
    group.append(title);
    this.inputsShown(box).forEach((input, i) => group.append(...this.port(box, input, "in", i)));
    box.outputs.forEach((output, i) => group.append(...this.port(box, output, "out", i)));
    const hidden = box.inputs.length - this.inputsShown(box).length;
    if (box.kind === "node" && (hidden > 0 || this.expanded.has(box.id))) {
      const toggle = element("text", { x: place.width - 8, y: 15, class: "toggle", "text-anchor": "end" });
      toggle.textContent = this.expanded.has(box.id) ? "−" : `+${hidden}`;
      toggle.addEventListener("click", (event) => {
        event.stopPropagation();
        this.expanded.has(box.id) ? this.expanded.delete(box.id) : this.expanded.add(box.id);
        this.draw(this.graph);
      });
      group.append(toggle);
    }
    group.addEventListener("click", () => this.select({ box: box.id }));
    group.addEventListener("dblclick", () => box.kind === "nodegraph" && this.actions.enter(box.id));
    this.svg.append(group);
  }

  port(box, port, side, index) {
    const y = TITLE + index * PORT + PORT / 2, x = side === "in" ? 0 : BOX_WIDTH;
    const dot = element("circle", { cx: x, cy: y, r: 5, fill: TYPE_COLOURS[port.type] ?? "#aaa", class: `port ${side}`,
                                    "data-port": port.name, "data-side": side, "data-type": port.type });
    const label = element("text", { x: side === "in" ? 9 : BOX_WIDTH - 9, y: y + 4, class: "port-name" + (port.connected ? " connected" : ""),
                                    "text-anchor": side === "in" ? "start" : "end" });
    label.textContent = side === "in" && !port.connected && port.value !== null && box.id !== GRAPH_OUTPUTS
      ? `${port.name} = ${short(port.value)}` : port.name;
    const title = element("title");
    title.textContent = `${port.name}: ${port.type}`;
    dot.append(title);
    if (side === "out") dot.addEventListener("pointerdown", (event) => this.drag(event, { box: box.id, port: port.name }));
    return [dot, label];
  }

  // Drag a new wire from an output; dropped on an input port, it asks the page to connect.
  drag(event, from) {
    event.preventDefault();
    event.stopPropagation();
    const start = this.portPoint(from.box, "out", from.port);
    const line = element("path", { class: "wire dragging", d: curve(start, start) });
    this.svg.append(line);
    const point = (e) => {
      const box = this.svg.getBoundingClientRect();
      return { x: e.clientX - box.left, y: e.clientY - box.top };
    };
    const move = (e) => line.setAttribute("d", curve(start, point(e)));
    const up = (e) => {
      window.removeEventListener("pointermove", move);
      window.removeEventListener("pointerup", up);
      line.remove();
      const target = document.elementFromPoint(e.clientX, e.clientY)?.closest?.("[data-side=in]");
      const boxId = target?.closest("[data-box]")?.dataset.box;
      if (!target || !boxId) return;
      const to = { box: boxId, port: target.dataset.port };
      const reason = this.actions.connect(from, to);
      this.refusal = reason ? { text: reason, at: to } : null;
      if (reason) this.showRefusal(reason, to);
    };
    window.addEventListener("pointermove", move);
    window.addEventListener("pointerup", up);
  }

  // The reason over the input it was dropped on, on a backing of its own so it reads over wires.
  showRefusal(text, at) {
    const p = this.portPoint(at.box, "in", at.port);
    const note = element("text", { x: p.x + 8, y: p.y - 10, class: "refusal" });
    note.textContent = `✕ ${text}`;
    this.svg.append(note);
    const box = note.getBBox();
    this.svg.insertBefore(element("rect", { x: box.x - 3, y: box.y - 2, width: box.width + 6, height: box.height + 4,
                                            rx: 3, class: "refusal-backing" }), note);
  }

  select(selection) {
    this.selection = selection;
    this.refusal = null;
    this.actions.select(selection);
  }
}

function curve(a, b) {
  const dx = Math.max(30, Math.abs(b.x - a.x) / 2);
  return `M${a.x},${a.y} C${a.x + dx},${a.y} ${b.x - dx},${b.y} ${b.x},${b.y}`;
}

const short = (value) => (value.length > 14 ? value.slice(0, 13) + "…" : value);

function element(name, attributes = {}) {
  const node = document.createElementNS(SVG, name);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, String(value));
  return node;
}
