// A MaterialX document written as a USD layer: each material a UsdShade Material whose
// outputs:mtlx:surface reads a network of Shader prims named by their nodedefs (`info:id =
// "ND_standard_surface_surfaceshader"`) and NodeGraph prims, as usdMtlx writes MaterialX; a
// standard_surface whose inputs the model can carry also gets a UsdPreviewSurface on
// outputs:surface, for renderers without MaterialX. Our USD reader (shadergen/usd_network.py)
// reads the MaterialX network back into the same graph.

import { GRAPH_INPUTS, GRAPH_OUTPUTS, readScope, source } from "./graph.js";

const ROOT = "/MaterialX";
const USD_TYPES = { float: "float", integer: "int", boolean: "bool", string: "string", filename: "asset",
  color3: "color3f", color4: "color4f", vector2: "float2", vector3: "float3", vector4: "float4",
  matrix33: "matrix3d", matrix44: "matrix4d" };
// standard_surface inputs UsdPreviewSurface has a meaning for (value inputs only)
const PREVIEW_INPUTS = { base_color: ["diffuseColor", "color3f"], metalness: ["metallic", "float"],
  specular_roughness: ["roughness", "float"], coat: ["clearcoat", "float"], coat_roughness: ["clearcoatRoughness", "float"],
  specular_IOR: ["ior", "float"], emission_color: ["emissiveColor", "color3f"] };

// The layer's text; `library` (library.js) names each node's nodedef. Throws an Error naming
// the element that USD cannot carry.
export function toUsda(xml, library) {
  const fileprefix = xml.documentElement.getAttribute("fileprefix") ?? "";
  const top = readScope(xml, "", library);
  const shaders = `${ROOT}/Shaders`;
  const lines = ["#usda 1.0", "(", '    doc = "written by the ShaderX editor from a MaterialX document"', ")", "",
                 `def Scope "${ROOT.slice(1)}"`, "{"];
  for (const box of top.boxes.filter((b) => b.type === "material")) lines.push(...material(box, top.boxes, shaders), "");
  lines.push(`    def Scope "Shaders"`, "    {");
  const at = { boxes: top.boxes, scope: "", parent: shaders };
  for (const box of top.boxes.filter((b) => b.type !== "material" && b.kind !== GRAPH_OUTPUTS)) {
    lines.push(...prim(box, at, xml, library, fileprefix, 2));
  }
  lines.push("    }", "}", "");
  return lines.join("\n");
}

function material(box, boxes, shaders) {
  const lines = [`    def Material "${box.id}"`, "    {"];
  for (const input of box.inputs) {
    const from = source(input.element);
    if (!from) continue;
    const context = input.type === "surfaceshader" ? "surface" : input.type === "displacementshader" ? "displacement" : "volume";
    lines.push(`        token outputs:mtlx:${context}.connect = <${shaders}/${from.box}.outputs:${outputName(boxes, from)}>`);
    if (context === "surface" && boxes.find((b) => b.id === from.box)?.category === "standard_surface") {
      lines.push(`        token outputs:surface.connect = <${shaders}/${from.box}_preview.outputs:surface>`);
    }
  }
  lines.push("    }");
  return lines;
}

// A node as a Shader, a nodegraph as a NodeGraph holding its nodes. `at`: where it is, as
// { boxes (of its scope), scope (the scope's path in the document), parent (the scope's prim) }.
function prim(box, at, xml, library, fileprefix, depth) {
  const pad = "    ".repeat(depth), path = `${at.parent}/${box.id}`;
  const lines = [];
  if (box.kind === "nodegraph") {
    const scope = at.scope ? `${at.scope}/${box.id}` : box.id;
    const inner = { boxes: readScope(xml, scope, library).boxes, scope, parent: path };
    lines.push(`${pad}def NodeGraph "${box.id}"`, `${pad}{`);
    for (const input of box.inputs) lines.push(...attribute(input, at, fileprefix, pad + "    "));
    for (const output of inner.boxes.find((b) => b.id === GRAPH_OUTPUTS)?.inputs ?? []) {
      const from = source(output.element);
      const target = from ? `.connect = <${path}/${from.box}.outputs:${outputName(inner.boxes, from)}>` : "";
      lines.push(`${pad}    ${usdType(output.type)} outputs:${output.name}${target}`);
    }
    for (const node of inner.boxes.filter((b) => b.kind === "node")) lines.push(...prim(node, inner, xml, library, fileprefix, depth + 1));
    lines.push(`${pad}}`);
    return lines;
  }
  if (!box.definition) throw new Error(`${box.id}: no nodedef of ${box.category} (${box.type}) to name in info:id`);
  lines.push(`${pad}def Shader "${box.id}"`, `${pad}{`, `${pad}    uniform token info:id = "${box.definition.name}"`);
  for (const input of box.inputs.filter((i) => i.present)) lines.push(...attribute(input, at, fileprefix, pad + "    "));
  for (const output of box.outputs) lines.push(`${pad}    ${usdType(output.type)} outputs:${output.name}`);
  lines.push(`${pad}}`);
  if (box.category === "standard_surface" && !at.scope) lines.push(...preview(box, pad));
  return lines;
}

// One input: its value, or its connection to a box of its scope or to its graph's interface.
function attribute(input, at, fileprefix, pad) {
  const type = usdType(input.type);
  const from = source(input.element);
  if (from) {
    const target = from.box === GRAPH_INPUTS ? `${at.parent}.inputs:${from.port}`
      : `${at.parent}/${from.box}.outputs:${outputName(at.boxes, from)}`;
    return [`${pad}${type} inputs:${input.name}.connect = <${target}>`];
  }
  if (input.value === null || !input.present) return [];
  const colorspace = input.element?.getAttribute("colorspace");
  const metadata = colorspace ? ` (\n${pad}    colorSpace = "${colorspace}"\n${pad})` : "";
  const text = input.type === "filename" ? fileprefix + input.value : input.value;
  return [`${pad}${type} inputs:${input.name} = ${usdValue(input.type, text)}${metadata}`];
}

// The output a connection reads: the one it names, else its box's only output.
function outputName(boxes, from) {
  return from.port ?? boxes.find((b) => b.id === from.box)?.outputs[0]?.name ?? "out";
}

// A UsdPreviewSurface of the values it can carry; inputs wired in MaterialX keep its defaults.
function preview(box, pad) {
  const lines = [`${pad}def Shader "${box.id}_preview"`, `${pad}{`, `${pad}    uniform token info:id = "UsdPreviewSurface"`];
  for (const input of box.inputs) {
    const mapped = PREVIEW_INPUTS[input.name];
    if (mapped && input.present && !input.connected && input.value !== null) {
      lines.push(`${pad}    ${mapped[1]} inputs:${mapped[0]} = ${usdValue(input.type, input.value)}`);
    }
  }
  lines.push(`${pad}    token outputs:surface`, `${pad}}`);
  return lines;
}

function usdType(type) {
  return USD_TYPES[type] ?? "token";  // closures and shaders are tokens in UsdShade
}

function usdValue(type, text) {
  if (type === "string") return JSON.stringify(text);
  if (type === "filename") return `@${text.replace(/@/g, "")}@`;
  if (type === "boolean") return text.trim() === "true" ? "1" : "0";
  const numbers = text.split(",").map((part) => part.trim());
  if (type.startsWith("matrix")) {
    const size = type === "matrix33" ? 3 : 4;
    const rows = Array.from({ length: size }, (_, r) => `(${numbers.slice(r * size, r * size + size).join(", ")})`);
    return `(${rows.join(", ")})`;
  }
  return numbers.length === 1 ? numbers[0] : `(${numbers.join(", ")})`;
}
