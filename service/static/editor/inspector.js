// The selected box's inputs: a value field for each one not wired (its text as the document
// writes it), the source of each wired one with a button to disconnect it, and Delete.

import { GRAPH_INPUTS, GRAPH_OUTPUTS } from "./graph.js";

// actions: { value(box, input, text), disconnect(to), remove(boxId) }
export function showInspector(container, box, actions) {
  container.replaceChildren();
  if (!box) return;
  const heading = document.createElement("h3");
  heading.textContent = box.category ? `${box.label} (${box.definition?.name ?? box.category})` : box.label;
  container.append(heading);
  for (const input of box.inputs) {
    const row = document.createElement("div");
    row.className = "inspector-row";
    row.dataset.input = input.name;
    const label = document.createElement("label");
    label.textContent = input.name;
    label.title = input.type;
    row.append(label);
    if (input.connected) {
      const from = document.createElement("span");
      const element = input.element;
      from.textContent = "← " + (element.getAttribute("nodename") || element.getAttribute("nodegraph") ||
                                 `${GRAPH_INPUTS} ${element.getAttribute("interfacename")}`) +
                         (element.getAttribute("output") ? `.${element.getAttribute("output")}` : "");
      row.append(from, button("disconnect", () => actions.disconnect({ box: box.id, port: input.name })));
    } else if (box.id !== GRAPH_OUTPUTS && input.type !== "surfaceshader" && !/shader$|^material$|^[BEV]DF$/.test(input.type)) {
      const field = document.createElement("input");
      field.value = input.value ?? "";
      field.placeholder = input.type;
      field.addEventListener("change", () => actions.value(box, input, field.value.trim()));
      row.append(field);
    }
    container.append(row);
  }
  if (box.id !== GRAPH_INPUTS && box.id !== GRAPH_OUTPUTS) container.append(button("delete node", () => actions.remove(box.id)));
}

function button(text, onClick) {
  const b = document.createElement("button");
  b.type = "button";
  b.textContent = text;
  b.dataset.action = text;
  b.addEventListener("click", onClick);
  return b;
}
