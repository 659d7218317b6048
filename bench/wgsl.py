"""WGSL conformance and size: every renderable element of every document under the given folders,
generated for wgsl (and glsl, for the size ratio), each WGSL module validated by wgpu
(creating its shader module: naga inside wgpu-native, on a Vulkan device).

    .venv/bin/python bench/wgsl.py ../shared/corpus/resources/Materials/TestSuite/stdlib \
        ../shared/corpus/resources/Materials/TestSuite/pbrlib [--interface specialized] [--failures N]

Prints, per folder and in all: elements, generated %, validated % (of generated), and the median
and worst ratio of WGSL fragment lines to our GLSL fragment lines for the same element. A document
with no renderable element has no element to count (conformance.py skips those too).
"""
import argparse
import collections
import statistics
import sys
from pathlib import Path

from shadergen.api import generate_file
from shadergen.render.wgpu_device import wgsl_errors


def lines(text: str) -> int:
    return sum(1 for ln in text.splitlines() if ln.strip())


def first_error_line(message: str) -> str:
    """The validator's own sentence: the line after wgpu's "Caused by:" preamble."""
    useful = [ln.strip() for ln in message.splitlines() if ln.strip() and not ln.strip().startswith(("Caused", "In wgpu", "WGSL"))]
    return useful[0] if useful else message.strip()[:80]


def measure(folder: Path, interface: str, reasons: collections.Counter) -> dict:
    rows = []
    for doc in sorted(folder.rglob("*.mtlx")):
        glsl = {r["element"]: r for r in generate_file(str(doc), target="glsl", all=True, interface=interface)
                if "error" not in r}
        for rec in generate_file(str(doc), target="wgsl", all=True, interface=interface):
            if rec.get("error", {}).get("code") == "no_renderable_element":
                # nothing to count: as in conformance.py, which counts what the reference renders
                reasons[f"not counted: no renderable element in {doc.name}"] += 1
                continue
            row = {"generated": "error" not in rec, "valid": False, "ratio": None}
            if not row["generated"]:
                reasons[rec["error"]["message"][:90]] += 1
            else:
                errors = wgsl_errors({s: rec["stages"][s] for s in ("vertex", "pixel")})
                row["valid"] = not errors
                for message in errors.values():
                    reasons[f"invalid: {first_error_line(message)[:80]} ({doc.name})"] += 1
                if rec["element"] in glsl:
                    row["ratio"] = lines(rec["stages"]["pixel"]) / lines(glsl[rec["element"]]["stages"]["pixel"])
            rows.append(row)
    return summarize(rows)


def summarize(rows: list[dict]) -> dict:
    n = len(rows) or 1
    gen = [r for r in rows if r["generated"]]
    ratios = sorted(r["ratio"] for r in gen if r["ratio"] is not None)
    return {"elements": len(rows), "generated": 100 * len(gen) / n,
            "validated": 100 * sum(r["valid"] for r in gen) / (len(gen) or 1),
            "median": statistics.median(ratios) if ratios else float("nan"),
            "worst": ratios[-1] if ratios else float("nan"), "rows": rows}


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("folders", nargs="+", type=Path)
    p.add_argument("--interface", default="complete")
    p.add_argument("--failures", type=int, default=10, help="how many failure reasons to print")
    a = p.parse_args()
    reasons: collections.Counter = collections.Counter()
    print(f"{'folder':<40} {'elements':>8} {'generated':>10} {'validated':>10} {'lines wgsl/glsl median':>23} {'worst':>6}")
    everything = []
    for folder in a.folders:
        s = measure(folder, a.interface, reasons)
        everything += s["rows"]
        print(f"{folder.name:<40} {s['elements']:>8} {s['generated']:>9.1f}% {s['validated']:>9.1f}% "
              f"{s['median']:>23.2f} {s['worst']:>6.2f}")
    s = summarize(everything)
    print(f"{'all':<40} {s['elements']:>8} {s['generated']:>9.1f}% {s['validated']:>9.1f}% "
          f"{s['median']:>23.2f} {s['worst']:>6.2f}")
    for reason, count in reasons.most_common(a.failures):
        print(f"  {count:>4}  {reason}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
