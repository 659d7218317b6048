#!/usr/bin/env python3
"""Why conformance.py's interface figure is below 100 %: every element whose complete listing
differs from the reference's, sorted by cause. The scorer keys a uniform by its path, or by its
name where the listing gives no path; structural names (issue 23) share no names with the
reference, so a uniform the reference lists without a path can never match by name. Causes:

- `pathless`: the reference lists a uniform without a path (image's uv_scale and uv_offset, which
  its implementation adds); ours lists it at `<node>/<input>`, the same node and input;
- `unit factor`: the reference publishes a unit conversion's factor (`<node>_<input>_unit_in2`, no
  path); ours writes it as code (a client could not say what it binds to; the unit is in the topology);
- `appdata`: the geometric streams differ; `other`: anything else (listed).

  PYTHONPATH=$PWD .venv/bin/python bench/interface_causes.py ../shared/corpus [--target glsl]

It reads the reference's listings from conformance.py's cache (running the oracle for a document
not yet in it). Its last line: `interface causes: N elements | same S | pathless P | unit factor U | ...`,
each element counted once, under its first cause in the order other, appdata, unit factor, pathless.
"""
import argparse
import collections
import importlib.util
import os
import tempfile

from shadergen.api import DocumentFile, Generator

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "tools", "conformance.py")


def conformance_module(path: str):
    spec = importlib.util.spec_from_file_location("conformance", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


PRIORITY = ("other", "appdata", "unit factor", "pathless")  # an element is counted under its first cause


def causes(reference: dict, ours: dict, interface) -> tuple[list[str], list]:
    """The causes of the differences between two listings, and the differences no cause but
    `other` or `appdata` explains."""
    (rp, ra), (op, oa) = interface(reference), interface(ours)
    missing, extra = rp - op, op - rp
    # ours at `.../<node>/<input>`, where the reference keys the uniform `<node>_<input>` by name
    by_place = {("_".join(key.split("/")[-2:]), kind): (key, kind) for key, kind in extra}
    found, unexplained = set(), []
    for key, kind in sorted(missing):
        if (key, kind) in by_place:
            found.add("pathless")
            extra.discard(by_place[(key, kind)])
        elif key.endswith("_unit_in2"):
            found.add("unit factor")
        else:
            found.add("other")
            unexplained.append(("missing", key, kind))
    if extra:
        found.add("other")
        unexplained += [("extra", key, kind) for key, kind in sorted(extra)]
    if ra != oa:
        found.add("appdata")
        unexplained.append(("appdata reference-ours", sorted(ra - oa), "ours-reference", sorted(oa - ra)))
    return sorted(found, key=PRIORITY.index), unexplained


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("corpus")
    parser.add_argument("--target", default="glsl")
    parser.add_argument("--conformance", default=TOOLS, help="the shared tools' conformance.py")
    parser.add_argument("--oracle-python", default=os.path.join(os.environ.get(
        "ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python"))
    parser.add_argument("--oracle-cache", default=os.environ.get(
        "ORACLE_CACHE", os.path.join(tempfile.gettempdir(), "mx_oracle_cache")))
    args = parser.parse_args()
    conformance = conformance_module(args.conformance)
    gen = Generator()
    counts, listed = collections.Counter(), collections.defaultdict(list)
    documents = sorted(os.path.join(d, f) for d, _, fs in os.walk(args.corpus) for f in fs if f.endswith(".mtlx"))
    for path in documents:
        references = [r for r in conformance.oracle_records(args.oracle_python, path, args.target, args.oracle_cache)
                      if "stages" in r]
        if not references:
            continue
        ours = {r.get("element"): r for r in gen.records(DocumentFile(path), all=True, target=args.target,
                                                          interface="complete")}
        for reference in references:
            record = ours.get(reference["element"])
            if record is None or "stages" not in record:
                counts["not generated"] += 1
                continue
            found, unexplained = causes(reference, record, conformance.interface)
            cause = found[0] if found else "same"
            counts[cause] += 1
            where = f"{os.path.relpath(path, args.corpus)}:{reference['element']}"
            listed[cause].append(f"{where} {unexplained[:3]}" if cause in ("other", "appdata") else where)
    for cause in sorted(listed):
        if cause != "same":
            print(f"{cause} ({len(listed[cause])}):")
            for line in listed[cause]:
                print(f"  {line}")
    order = ["same", "pathless", "unit factor", "appdata", "other", "not generated"]
    print(f"interface causes: {sum(counts.values())} elements | "
          + " | ".join(f"{cause} {counts[cause]}" for cause in order))


if __name__ == "__main__":
    main()
