// Every edit of the document, from the controls, the graph or undo and redo: a value edit
// changes the document text and the uniform on the GPU, with no request (the topology is the
// same); a topology edit (a node added or deleted, a wire made or taken away) changes the text
// and asks the server for the new record. Each is timed from the edit to its frame.

import { parseDocument, serialize, setInputValue } from "./documents.js";
import { History } from "./history.js";

export class Edits {
  // page: { state, textarea, run() -> Promise<bool: a record shown>, refresh() (controls, graph) }
  constructor(page) {
    this.page = page;
    this.history = new History();
    this.timings = { value: [], topology: [] };  // ms from an edit to its frame
  }

  // A value typed for an input (`path`: graph/node/input); returns the reason when refused.
  value(path, type, text) {
    const { state, textarea } = this.page;
    const before = textarea.value;
    if (!state.xml || !setInputValue(state.xml, path, type, text)) return `${path} takes no value here (wired, or not in the document)`;
    const after = serialize(state.xml);
    textarea.value = after;
    const variable = uniforms(state.record).find((v) => v.path === path);
    if (!variable) {  // an input the listing does not publish: only a new record shows it
      this.history.record({ before, after, kind: "topology" });
      this.regenerate();
      return null;
    }
    const uniform = { variable, before: variable.value, after: uniformValue(variable, type, text) };
    this.history.record({ before, after, kind: "value", uniform });
    this.apply(variable, uniform.after);
    this.page.refresh();
    return null;
  }

  // A control moved: the same as typing its value, the control already showing it.
  control(variable, value, text, type) {
    const { state, textarea } = this.page;
    const before = textarea.value;
    if (state.xml && variable.path && setInputValue(state.xml, variable.path, type, text)) textarea.value = serialize(state.xml);
    this.history.record({ before, after: textarea.value, kind: "value", uniform: { variable, before: variable.value, after: value } });
    this.apply(variable, value);
  }

  // A topology edit: `mutate(xml)` returns the reason it refuses (and then changed nothing).
  topology(mutate) {
    const { state, textarea } = this.page;
    if (!state.xml) return "there is no MaterialX document to edit";
    const before = textarea.value;
    const reason = mutate(state.xml);
    if (reason) return reason;
    textarea.value = serialize(state.xml);
    this.history.record({ before, after: textarea.value, kind: "topology" });
    this.regenerate();
    return null;
  }

  undo() {
    const edit = this.history.undo();
    if (edit) this.restore(edit.before, edit, "before");
    return edit !== null;
  }

  redo() {
    const edit = this.history.redo();
    if (edit) this.restore(edit.after, edit, "after");
    return edit !== null;
  }

  restore(text, edit, side) {
    const { state, textarea } = this.page;
    textarea.value = text;
    if (edit.kind !== "value") return this.regenerate();
    state.xml = parseDocument(text);
    this.apply(edit.uniform.variable, edit.uniform[side]);
    this.page.refresh();
  }

  apply(variable, value) {
    const { state } = this.page;
    const started = performance.now();
    variable.value = value;
    if (!state.preview) return;
    if (variable.type === "filename") state.preview.reloadTextures(state.record);
    else state.preview.setUniform(variable.name, value);
    state.preview.nextFrame().then(() => this.timings.value.push(performance.now() - started));
  }

  async regenerate() {
    const started = performance.now();
    if (await this.page.run() && this.page.state.preview) {
      await this.page.state.preview.nextFrame();
      this.timings.topology.push(performance.now() - started);
    }
  }
}

function uniforms(record) {
  return Object.values(record?.blocks ?? {}).flatMap((stage) => stage.PublicUniforms ?? []);
}

// A document value's text as its uniform takes it: numbers, lists of them, booleans, a string
// enum as the index of its name (how the listing publishes it).
function uniformValue(variable, type, text) {
  if (variable.ui?.enum && variable.type === "integer" && type === "string") return Math.max(0, variable.ui.enum.indexOf(text));
  if (type === "boolean") return text.trim() === "true";
  if (type === "float" || type === "integer") return Number(text);
  if (/^(color|vector)[234]$|^matrix/.test(type)) return text.split(",").map(Number);
  return text;
}
