// The library's node definitions (GET /v1/nodedefs) as the graph editor asks for them: the
// definition an element uses, and a search over all of them for the palette.

export class Library {
  constructor(nodedefs) {
    this.nodedefs = nodedefs;
    this.byName = new Map(nodedefs.map((nodedef) => [nodedef.name, nodedef]));
    this.byNode = new Map();
    for (const nodedef of nodedefs) {
      if (!this.byNode.has(nodedef.node)) this.byNode.set(nodedef.node, []);
      this.byNode.get(nodedef.node).push(nodedef);
    }
  }

  // The nodedef of an element: the one it names, else among its category's of its output type
  // (several outputs for "multioutput") the one whose inputs its own typed inputs fit best.
  definition(element) {
    const named = element.getAttribute("nodedef");
    if (named && this.byName.has(named)) return this.byName.get(named);
    const type = element.getAttribute("type");
    const candidates = (this.byNode.get(element.localName) ?? []).filter((nodedef) =>
      type === "multioutput" ? nodedef.outputs.length > 1 : nodedef.outputs.length === 1 && nodedef.outputs[0].type === type);
    const own = [...element.children].filter((child) => child.localName === "input");
    const fit = (nodedef) => own.filter((input) =>
      nodedef.inputs.some((port) => port.name === input.getAttribute("name") && port.type === input.getAttribute("type"))).length;
    return candidates.sort((a, b) => fit(b) - fit(a))[0] ?? null;
  }

  // Definitions whose name, node or group holds every word of `text`, best (shortest name) first.
  search(text, limit = 40) {
    const words = text.toLowerCase().split(/\s+/).filter(Boolean);
    return this.nodedefs
      .filter((nodedef) => words.every((word) => `${nodedef.name} ${nodedef.node} ${nodedef.nodegroup ?? ""}`.toLowerCase().includes(word)))
      .sort((a, b) => a.name.length - b.name.length || a.name.localeCompare(b.name))
      .slice(0, limit);
  }
}
