// Undo and redo of the document's edits, as the document text before and after each one, with
// its kind: a value edit is undone on the GPU like it was made, anything else asks the server.

const LIMIT = 200;

export class History {
  constructor() {
    this.done = [];
    this.undone = [];
  }

  // `edit`: { before, after, kind: "value" | "topology", uniform?: { name, before, after } }
  record(edit) {
    this.done.push(edit);
    if (this.done.length > LIMIT) this.done.shift();
    this.undone = [];
  }

  undo() {
    const edit = this.done.pop();
    if (edit) this.undone.push(edit);
    return edit ?? null;
  }

  redo() {
    const edit = this.undone.pop();
    if (edit) this.done.push(edit);
    return edit ?? null;
  }
}
