// Automatic layered layout of a graph (graph.js): a box's column is its longest wire path to
// the graph's end (materials and outputs rightmost, sources leftmost), boxes in a column ordered
// by the mean height of their neighbours (a few sweeps each way, which untangles most wires),
// then stacked. Returns box id -> { x, y, width, height } and the drawing's size.

export const BOX_WIDTH = 170, TITLE = 22, PORT = 16, GAP_X = 70, GAP_Y = 18, MARGIN = 20;
const SWEEPS = 4;

export function boxHeight(box, shown) {
  return TITLE + PORT * Math.max(shown.inputs(box).length, box.outputs.length) + 6;
}

// `shown.inputs(box)`: the input ports drawn for a box (the view may hide unset ones)
export function layout({ boxes, wires }, shown) {
  const feeds = new Map(boxes.map((box) => [box.id, []]));   // id -> ids it feeds
  const reads = new Map(boxes.map((box) => [box.id, []]));   // id -> ids it reads from
  for (const { from, to } of wires) {
    feeds.get(from.box)?.push(to.box);
    reads.get(to.box)?.push(from.box);
  }
  const depth = new Map();  // longest path to a box that feeds nothing, cycles cut where met
  const visit = (id, trail) => {
    if (depth.has(id)) return depth.get(id);
    if (trail.has(id)) return 0;
    trail.add(id);
    const d = Math.max(-1, ...feeds.get(id).map((next) => visit(next, trail))) + 1;
    trail.delete(id);
    depth.set(id, d);
    return d;
  };
  boxes.forEach((box) => visit(box.id, new Set()));
  const columns = Math.max(0, ...depth.values()) + 1;
  const layers = Array.from({ length: columns }, () => []);
  for (const box of boxes) layers[columns - 1 - depth.get(box.id)].push(box);

  const rank = new Map();
  const number = () => layers.forEach((layer) => layer.forEach((box, i) => rank.set(box.id, i)));
  number();
  const meanRank = (ids, fallback) => (ids.length ? ids.reduce((sum, id) => sum + rank.get(id), 0) / ids.length : fallback);
  for (let sweep = 0; sweep < SWEEPS; sweep++) {
    const order = sweep % 2 === 0 ? layers.slice(1) : layers.slice(0, -1).reverse();
    for (const layer of order) {
      const neighbours = (box) => (sweep % 2 === 0 ? reads : feeds).get(box.id);
      const keys = new Map(layer.map((box) => [box.id, meanRank(neighbours(box), rank.get(box.id))]));
      layer.sort((a, b) => keys.get(a.id) - keys.get(b.id));
      number();
    }
  }

  const places = new Map();
  const heights = layers.map((layer) => layer.reduce((sum, box) => sum + boxHeight(box, shown) + GAP_Y, -GAP_Y));
  const tallest = Math.max(0, ...heights);
  layers.forEach((layer, column) => {
    let y = MARGIN + (tallest - heights[column]) / 2;
    for (const box of layer) {
      const height = boxHeight(box, shown);
      places.set(box.id, { x: MARGIN + column * (BOX_WIDTH + GAP_X), y, width: BOX_WIDTH, height });
      y += height + GAP_Y;
    }
  });
  return { places, width: 2 * MARGIN + columns * (BOX_WIDTH + GAP_X) - GAP_X, height: 2 * MARGIN + tallest };
}
