"""`shadergen render`: a material thumbnail from a document (through our generator) or from any
shader record (--record: ours, the reference oracle's, hand-written). Errors are one line on
stderr (and a JSON error object on stdout with --json) and exit code 1, never a traceback."""
import json
import os
import sys
from pathlib import Path

from shadergen.cli_generate import add_cms_arguments, cms_options
from shadergen.errors import ShaderGenError

from . import Environment, RenderError, Renderer
from .batch import display_encoders
from .imageio import write_image
from .renderer import ENV_METHODS

# backend -> the target a document is generated for
BACKENDS = {"gl": "glsl", "wgpu": "wgsl", "vulkan": "vulkan"}


TEXTURE_ROOTS_VARIABLE = "SHADERGEN_TEXTURE_ROOTS"
EXAMPLES = f"""examples:
  shadergen render examples/marble_checker.mtlx -o marble.png
  shadergen render brass.mtlx --element Tiled_Brass --env studio.hdr --lights rig.mtlx -o brass.png --exr brass.exr
  shadergen generate doc.mtlx > rec.jsonl && shadergen render --record rec.jsonl --npy linear.npy
  shadergen render --batch library/ -o thumbnails/     # every material of every document under library/

--batch DIR_OR_LIST renders every material of every document under a folder (or named one per line
in a list file) in this one process, with a progress bar: OUTDIR/<document>/<element>.png, and
OUTDIR/results.jsonl with one line per material (its PNG, or its error record). One program is
compiled per topology: the batch generates `complete` (value-free) source unless --interface says.

textures: a relative file name is looked up in the document's folder, then in each --search-path,
then in each folder of ${TEXTURE_ROOTS_VARIABLE} (':'-separated). The command line reads whatever
file the document names (../../Images/ included); --confine reads only from those folders and
--texture-root, as the service does."""


def add_arguments(parser) -> None:
    parser.add_argument("document", nargs="?", help="MaterialX document (.mtlx) to generate and render")
    parser.add_argument("--batch", metavar="DIR_OR_LIST",
                        help="thumbnails of every material of every document under DIR (or listed in a file, one "
                             "path a line) into -o OUTDIR; see below")
    parser.add_argument("--record", metavar="REC.json",
                        help="render this shader record (JSON, or JSON Lines: first record or --element; - for stdin)")
    parser.add_argument("--element", metavar="NAMEPATH", help="renderable element (default: the first)")
    parser.add_argument("--backend", choices=tuple(BACKENDS), default="gl",
                        help="gl: our GLSL drawn with OpenGL on EGL; wgpu: our WGSL drawn with WebGPU on Vulkan "
                             "(lavapipe without a GPU); vulkan: our Vulkan GLSL's SPIR-V drawn by the same WebGPU "
                             "device; the same scene in all three")
    parser.add_argument("--interface",
                        help="interface of the generated shader (default specialized: values folded into the code, "
                             "the same image as complete, the smallest shader; with --batch complete, one program per "
                             "topology); complete | reduced | specialized")
    parser.add_argument("-o", "--output", metavar="OUT.png",
                        help="sRGB PNG composited on --background (with --batch: the folder of the PNGs)")
    parser.add_argument("--exr", metavar="OUT.exr", help="linear RGBA EXR")
    parser.add_argument("--npy", metavar="OUT.npy", help="the linear RGBA float32 framebuffer, top row first")
    parser.add_argument("--size", type=int, default=256, help="image width and height in pixels")
    parser.add_argument("--ss", type=int, default=1, metavar="N", help="supersample N x N per pixel")
    parser.add_argument("--mesh", default="sphere", help="sphere, plane, or a .obj file")
    parser.add_argument("--env", metavar="LATLONG", help="lat-long radiance map (.hdr/.exr); default: procedural sky")
    parser.add_argument("--irr", metavar="LATLONG", help="lat-long irradiance map; default: computed from --env")
    parser.add_argument("--env-intensity", type=float, default=1.0, help="u_envLightIntensity")
    parser.add_argument("--env-samples", type=int, help="u_envRadianceSamples (with --env-method fis or hybrid; "
                                                        "default 16 and 4)")
    parser.add_argument("--env-method", choices=ENV_METHODS, default="fis",
                        help="environment lighting: fis (filtered importance sampling, --env-samples per pixel), "
                             "prefilter (a GGX-prefiltered map and a DFG table: one lookup) or hybrid (that lookup "
                             "corrected by --env-samples samples of the prefiltered map)")
    parser.add_argument("--lights", metavar="LIGHTS.mtlx", help="light rig: a document of lightshader nodes")
    parser.add_argument("--search-path", action="append", default=[], metavar="DIR",
                        help="folder to resolve texture names in after the document's own (repeatable)")
    parser.add_argument("--texture-root", action="append", default=[], metavar="DIR",
                        help="further folder textures may be read from with --confine (repeatable)")
    parser.add_argument("--confine", action="store_true",
                        help="read textures only from the document's folder, search paths and texture roots")
    parser.add_argument("--background", type=float, default=0.18, help="linear grey behind the object in the PNG")
    parser.add_argument("--repeat", type=int, default=1, metavar="N", help="draw N frames to time a steady frame")
    parser.add_argument("--json", action="store_true", help="print a JSON summary (or error) on stdout")
    add_cms_arguments(parser)  # with ocio, the PNG shows the working space through the config's display and view
    parser.add_argument("--view", help="with --cms ocio: the view of the config's default display the PNG shows "
                        "(default: the config's default view; the CG config's is tone-mapped, 'Un-tone-mapped' is not)")


def run(args) -> int:
    try:
        return _run(args)
    except ShaderGenError as exc:
        return _fail(args, exc.to_dict())
    except Exception as exc:  # the contract: a message, never a traceback
        return _fail(args, {"code": "internal_error", "message": f"{type(exc).__name__}: {exc}", "where": None})


def _fail(args, error: dict) -> int:
    where = f" (at {error['where']})" if error.get("where") else ""
    print(f"shadergen render: {error['code']}: {error['message']}{where}", file=sys.stderr)
    if args.json:
        print(json.dumps({"document": args.document, "element": args.element, "error": error}))
    return 1


def _run(args) -> int:
    outputs = [p for p in (args.output, args.exr, args.npy) if p]
    if not outputs:
        raise RenderError("invalid_request", "nothing to write: give -o OUT.png, --exr or --npy")
    if sum(map(bool, (args.document, args.record, args.batch))) != 1:
        raise RenderError("invalid_request", "give one of a document, --record REC.json or --batch DIR_OR_LIST")
    if args.irr and not args.env:
        raise RenderError("invalid_request", "--irr needs --env (the procedural sky computes its own)")
    if args.batch:
        from .batch import run_batch
        return run_batch(args, _renderer(args), _environment(args), BACKENDS[args.backend])
    record = _record_from_file(args.record, args.element) if args.record \
        else _record_from_document(args.document, args.element, args.interface or "specialized",
                                   BACKENDS[args.backend], args.env_method, bool(args.lights), cms_options(args))
    encoder = display_encoders(args)  # an unknown view fails before the render
    env = _environment(args)
    document_dir = os.path.dirname(os.path.abspath(args.document)) if args.document else None
    renderer = _renderer(args)
    result = renderer.render(record, size=args.size, mesh=args.mesh, env=env, env_samples=args.env_samples,
                             env_method=args.env_method,
                             lights=args.lights, supersample=args.ss, document_dir=document_dir,
                             frames=args.repeat)
    encode = encoder(record)  # the record names its working space (any document format, or --record)
    for path in outputs:  # .exr and .npy keep the linear working-space values
        write_image(path, result.rgba, background=args.background, encode=encode)
    for warning in result.warnings:
        print(f"shadergen render: warning: {warning}", file=sys.stderr)
    t = result.timings_ms
    print(f"shadergen render: {record.get('element') or 'record'} {args.size}x{args.size}"
          f"{f' ss{args.ss}' if args.ss > 1 else ''}: compile+link {t['compile_link']:.1f} ms, "
          f"first frame {t['first_frame']:.1f} ms, frame {t['frame']:.1f} ms", file=sys.stderr)
    if args.json:
        print(json.dumps({"document": args.document or record.get("document"), "element": record.get("element"),
                          "outputs": outputs, "timings_ms": t, "warnings": result.warnings}))
    return 0


def _environment(args) -> Environment:
    return Environment.load(args.env, args.irr, args.env_intensity) if args.env else Environment.procedural(args.env_intensity)


def _renderer(args):
    env_roots = [p for p in os.environ.get(TEXTURE_ROOTS_VARIABLE, "").split(os.pathsep) if p]
    renderer_class = Renderer
    if args.backend in ("wgpu", "vulkan"):
        from .wgpu_renderer import WgpuRenderer as renderer_class  # imports wgpu only when asked for
    return renderer_class(texture_roots=args.texture_root + env_roots, search_paths=args.search_path + env_roots,
                          confined=args.confine)


def _record_from_file(path: str, element: str | None) -> dict:
    try:
        text = sys.stdin.read() if path == "-" else Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise RenderError("invalid_record", f"cannot read {path}: {getattr(exc, 'strerror', None) or exc}", path) from exc
    try:
        records = [json.loads(text)]
    except json.JSONDecodeError:
        try:  # JSON Lines, as `generate` and the oracle print
            records = [json.loads(line) for line in text.splitlines() if line.strip()]
        except json.JSONDecodeError as exc:
            raise RenderError("invalid_record", f"{path} is neither JSON nor JSON Lines: {exc}", path) from exc
    return _choose(records, element, path)


def _record_from_document(path: str, element: str | None, interface: str, target: str, env_method: str,
                          lights: bool, cms: dict) -> dict:
    """The document's record, generated for the environment lighting it is drawn with, and with a
    light loop only when a light rig is drawn."""
    try:
        from shadergen.api import generate_file
    except ImportError as exc:
        raise RenderError("unavailable", "this build has no generator (shadergen.api); render a record "
                          "with --record REC.json instead") from exc
    return _choose(generate_file(path, target=target, element=element, interface=interface, environment=env_method,
                                 lights=lights, **cms), element, path)


def _choose(records: list, element: str | None, source: str) -> dict:
    """The record of `element` (its name path), else the first that is not an error."""
    if element:
        matching = [r for r in records if isinstance(r, dict) and r.get("element") == element]
        if not matching:
            raise RenderError("invalid_request", f"no record for element {element!r} in {source}", element)
        return matching[0]  # an error record is reported as such by the renderer
    usable = [r for r in records if isinstance(r, dict) and "error" not in r]
    if usable:
        return usable[0]
    if records and isinstance(records[0], dict):
        return records[0]
    raise RenderError("invalid_record", f"{source} holds no shader record", source)
