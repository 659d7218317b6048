// The node palette: the library's definitions (GET /v1/nodedefs), searched as one types; a
// click adds a node of that definition to the scope shown.

export function buildPalette(search, list, library, add) {
  const refresh = () => {
    list.replaceChildren(...library.search(search.value).map((nodedef) => {
      const item = document.createElement("li");
      item.textContent = nodedef.name;
      item.title = `${nodedef.node} (${nodedef.nodegroup ?? "no group"}): ` +
        nodedef.inputs.map((input) => `${input.name} ${input.type}`).join(", ") + " → " +
        nodedef.outputs.map((output) => output.type).join(", ");
      item.dataset.nodedef = nodedef.name;
      item.addEventListener("click", () => add(nodedef));
      return item;
    }));
  };
  search.addEventListener("input", refresh);
  refresh();
}
