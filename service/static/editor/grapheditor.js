// The graph panel: the scope shown (the document, or a nodegraph entered by double-click, left
// by its breadcrumb), its drawing, the inspector of the selected box and the palette. Edits go
// to the page (`page.topology(mutate)`, `page.value(path, type, text)`), which changes the
// document, the preview and the history, then asks the panel to draw again.

import { readScope, scopeElement } from "./graph.js";
import { addNode, connect, deleteBox, disconnect } from "./graphedits.js";
import { GraphView } from "./graphview.js";
import { showInspector } from "./inspector.js";
import { buildPalette } from "./palette.js";

export class GraphEditor {
  // elements: { canvas, crumbs, inspector, search, palette, note }; page: { xml(), topology(mutate), value(path, type, text) }
  constructor(elements, library, page) {
    this.elements = elements;
    this.library = library;
    this.page = page;
    this.scope = "";
    this.view = new GraphView(elements.canvas, {
      select: () => this.show(),
      enter: (id) => this.enter(this.scope ? `${this.scope}/${id}` : id),
      connect: (from, to) => this.edit((xml) => connect(xml, this.scope, library, from, to)),
    });
    buildPalette(elements.search, elements.palette, library, (nodedef) => {
      let name = null;
      this.edit((xml) => {
        name = addNode(xml, this.scope, nodedef);
        return null;
      });
      this.view.selection = { box: name };
      this.show();
    });
    window.addEventListener("keydown", (event) => {
      if (event.target.closest?.("input, textarea, select") || !["Delete", "Backspace"].includes(event.key)) return;
      const selection = this.view.selection;
      if (selection?.wire) this.edit((xml) => disconnect(xml, this.scope, library, selection.wire));
      else if (selection?.box) this.edit((xml) => deleteBox(xml, this.scope, library, selection.box));
    });
  }

  // A topology edit: refused edits change nothing and leave their reason in the note.
  edit(mutate) {
    const reason = this.page.topology(mutate);
    this.elements.note.textContent = reason ? `refused: ${reason}` : "";
    this.elements.note.classList.toggle("refused", Boolean(reason));
    if (!reason) this.show();
    return reason;
  }

  enter(scope) {
    this.scope = scope;
    this.view.selection = null;
    this.view.refusal = null;
    this.show();
  }

  // Draw the scope shown from the document as it is now (the top, if the scope is gone).
  show() {
    const xml = this.page.xml();
    if (!xml) {  // a USD layer or package: generated as it is, not drawn here
      this.view.draw({ boxes: [], wires: [] });
      this.elements.inspector.replaceChildren();
      return;
    }
    if (!scopeElement(xml, this.scope)) this.scope = "";
    const graph = readScope(xml, this.scope, this.library);
    this.graph = graph;
    this.view.draw(graph);
    this.showCrumbs();
    const box = graph.boxes.find((b) => b.id === this.view.selection?.box) ?? null;
    showInspector(this.elements.inspector, box, {
      value: (target, input, text) => this.page.value(this.pathOf(target, input), input.type, text),
      disconnect: (to) => this.edit((doc) => disconnect(doc, this.scope, this.library, to)),
      remove: (id) => {
        this.view.selection = null;
        this.edit((doc) => deleteBox(doc, this.scope, this.library, id));
      },
    });
  }

  pathOf(box, input) {
    const prefix = this.scope ? `${this.scope}/` : "";
    return box.kind === "node" || box.kind === "nodegraph" ? `${prefix}${box.id}/${input.name}` : `${this.scope}/${input.name}`;
  }

  showCrumbs() {
    const parts = this.scope ? this.scope.split("/") : [];
    const crumb = (label, scope) => {
      const link = document.createElement("button");
      link.type = "button";
      link.textContent = label;
      link.dataset.scope = scope;
      link.disabled = scope === this.scope;
      link.addEventListener("click", () => this.enter(scope));
      return link;
    };
    this.elements.crumbs.replaceChildren(crumb("document", ""), ...parts.map((part, i) => crumb(part, parts.slice(0, i + 1).join("/"))));
  }
}
