// What the page saves: the edited .mtlx, the material as a .usda (usda.js), the preview as a PNG,
// each a download made in the browser; and a link that reopens the document (share.js).

import { linkFor } from "./share.js";
import { toUsda } from "./usda.js";

export function download(blob, name) {
  const link = document.createElement("a");
  link.href = URL.createObjectURL(blob);
  link.download = name;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(link.href), 60_000);
}

// page: { text(), xml(), library(), canvas, name() (the file name without its extension) }
export function installExports(buttons, page, report) {
  const guard = (action) => async () => {
    try {
      await action();
    } catch (failure) {
      report(failure);
    }
  };
  buttons.mtlx.addEventListener("click", guard(() => download(new Blob([page.text()], { type: "application/xml" }), `${page.name()}.mtlx`)));
  buttons.usda.addEventListener("click", guard(() => download(new Blob([usdaOf(page)], { type: "model/vnd.usda" }), `${page.name()}.usda`)));
  buttons.png.addEventListener("click", guard(async () => {
    const png = await new Promise((resolve) => page.canvas.toBlob(resolve, "image/png"));
    download(png, `${page.name()}.png`);
  }));
  buttons.link.addEventListener("click", guard(async () => {
    const link = await linkFor(page.text());
    buttons.linkField.value = link;
    buttons.linkField.hidden = false;
    buttons.linkField.select();
    await navigator.clipboard?.writeText(link).catch(() => {});  // headless or unfocused: the field shows it
  }));
  return { usda: () => usdaOf(page) };  // for the browser tests
}

function usdaOf(page) {
  if (!page.xml()) throw new Error("only a MaterialX document is written as .usda");
  return toUsda(page.xml(), page.library());
}
