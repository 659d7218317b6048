// A link that reopens a document: the text deflated (CompressionStream) and base64url-encoded in
// the URL's fragment, which the browser never sends, so nothing is stored on the server.

const KEY = "doc=";

export async function linkFor(text) {
  const packed = await new Response(new Blob([text]).stream().pipeThrough(new CompressionStream("deflate-raw"))).arrayBuffer();
  let binary = "";
  for (const byte of new Uint8Array(packed)) binary += String.fromCharCode(byte);
  const encoded = btoa(binary).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
  return `${location.origin}${location.pathname}#${KEY}${encoded}`;
}

// The document a link's fragment holds, or null when it holds none; throws on a damaged one.
export async function documentFromFragment(hash) {
  const fragment = hash.replace(/^#/, "");
  if (!fragment.startsWith(KEY)) return null;
  const base64 = fragment.slice(KEY.length).replace(/-/g, "+").replace(/_/g, "/");
  const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
  return new Response(new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate-raw"))).text();
}
