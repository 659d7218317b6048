#!/usr/bin/env python3
"""Conformance of every target (issue 24), one table: each renderable element of TestSuite/stdlib,
TestSuite/pbrlib and the Examples, generated for each target and interface, each stage checked by
its target's checker (`targets.checker_for`: glslangValidator for glsl and essl, wgpu's naga for
wgsl, glslangValidator -V + spirv-val for vulkan, the Slang compiler for hlsl and slang, the MSL
cross-check against naga's MSL of our WGSL of the same element for msl). Beside ours, the reference
generator's own output for the targets it has (glsl, essl, vulkan, slang, msl; complete interface:
the reference has no specialized one) through ../shared/oracle/mx_oracle.py, checked by the same
checkers. Where a target is drawn (essl by GL, wgsl and vulkan by WebGPU on lavapipe), the Examples
are drawn against our GLSL drawn by GL in the same scene (bench/wgsl_images.py compare_images),
specialized: the count at >= 40 dB PSNR and the lowest.

    .venv/bin/python bench/targets.py [--corpus ../shared/corpus] [--targets glsl,essl,...]
        [--interfaces complete,specialized] [--no-reference] [--no-images] [--sample N] [--failures N]
        [--journal FILE] [--no-conformance]

`--sample N` keeps every Nth document of each corpus (for development; the full run is the figure).
Prints a row per target, interface and corpus, the most common failures, and last
`targets: <target> gen% / valid% (ref gen% / valid%) [img n/N >= 40 dB] | ...` over all corpora.
"""
import argparse
import base64
import collections
import json
import math
import os
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from wgsl_images import PASS_DB, compare_images  # noqa: E402 - the image check of each drawn target

from shadergen.api import Generator  # noqa: E402
from shadergen.targets import checker_for  # noqa: E402
from shadergen.targets.checking import Unavailable  # noqa: E402
from shadergen.targets.msl.check import ENTRY as MSL_ENTRY, Declarations  # noqa: E402
from shadergen.targets.vulkan.check import spirv_errors  # noqa: E402

TARGETS = ("glsl", "essl", "wgsl", "vulkan", "hlsl", "slang", "msl")
CORPORA = {"stdlib": "resources/Materials/TestSuite/stdlib", "pbrlib": "resources/Materials/TestSuite/pbrlib",
           "Examples": "resources/Materials/Examples"}
REFERENCE_TARGETS = frozenset({"glsl", "essl", "vulkan", "slang", "msl"})  # MaterialX 1.39.5 has no HLSL; its
# "wgsl" generator writes Vulkan GLSL for a later translation, not WGSL
DRAWN = frozenset({"essl", "wgsl", "vulkan"})  # drawn against glsl on GL
ORACLE_PY = os.path.join(os.environ.get("ORACLE_VENV", os.path.expanduser("~/.cache/mx-oracle/venv")), "bin", "python")
SHARED = Path(os.environ.get("SHADERGEN_SHARED", HERE.parents[1] / "shared"))
# The oracle, run document by document in one process (its libraries loaded once), with two
# changes to ../shared/oracle/mx_oracle.py made here, not there: its factories() lists glsl, essl, osl,
# vulkan, wgsl and msl, not slang, so `--target slang` raises KeyError: 'slang', although the
# materialx 1.39.5 wheel ships PyMaterialXGenSlang (SlangShaderGenerator), which is added; and its
# value_json() calls Value.getData(), which some listing values lack (AttributeError on a TestSuite
# document, after the shader was generated), so such a value is written as its text. A document
# the oracle still fails on is one element not generated, with the exception as its message.
ORACLE = r"""
import json, sys
sys.path.insert(0, sys.argv[1])
import mx_oracle
listed, value_json = mx_oracle.factories, mx_oracle.value_json
def factories():
    found = listed()
    if "slang" not in found:
        import MaterialX.PyMaterialXGenSlang as slang
        found["slang"] = slang.SlangShaderGenerator.create
    return found
def value_or_text(v):
    try:
        return value_json(v)
    except AttributeError:
        return v.getValueString()
mx_oracle.factories, mx_oracle.value_json = factories, value_or_text
oracle = mx_oracle.Oracle(sys.argv[2], "complete")
for path in sys.argv[3:]:
    try:
        for record in oracle.run(path):
            print(json.dumps(record), flush=True)
    except Exception as exc:
        print(json.dumps({"document": path, "element": None, "error": {"code": "oracle_failed",
                          "message": f"{type(exc).__name__}: {exc}"}}), flush=True)
"""


def documents(corpus: Path, sample: int) -> dict[str, list[Path]]:
    return {name: sorted((corpus / folder).rglob("*.mtlx"))[::sample] for name, folder in CORPORA.items()}


def ours(generator: Generator, doc: Path, target: str, interface: str) -> list[dict]:
    return list(generator.records(doc, target=target, all=True, interface=interface))


def reference(docs: list[Path], target: str) -> dict[Path, list[dict]]:
    """The oracle's records per document (one oracle process for the lot)."""
    run = subprocess.run([ORACLE_PY, "-c", ORACLE, str(SHARED / "oracle"), target, *map(str, docs)],
                         capture_output=True, text=True)
    found: dict[Path, list[dict]] = {doc: [] for doc in docs}
    for line in run.stdout.splitlines():
        record = json.loads(line)
        found[Path(record["document"])].append(record)
    if run.returncode != 0:  # it died outside a document (its libraries, its generator)
        raise SystemExit(f"the oracle failed on {target}: {run.stderr.strip()[-400:]}")
    return found


def reference_msl_errors(shaders: dict[str, tuple[str, str]]) -> dict[str, str]:
    """The reference's MSL read alone (there is no WGSL of its own to cross-check it against):
    its declarations must read and declare an entry point of the stage's kind (it names them
    VertexMain / FragmentMain where ours are vertexMain / fragmentMain)."""
    found = {}
    for label, (stage, source) in shaders.items():
        try:
            kinds = {kind for kind, *_ in Declarations(source).entries.values()}
        except ValueError as exc:
            found[label] = str(exc)
            continue
        if MSL_ENTRY[stage][0] not in kinds:
            found[label] = f"no {MSL_ENTRY[stage][0]} entry point"
    return found


class Row:
    """One target, interface and corpus, of ours or the reference."""

    def __init__(self, elements: int = 0, generated: int = 0, valid: int = 0):
        self.elements, self.generated, self.valid = elements, generated, valid

    def counts(self) -> list[int]:
        return [self.elements, self.generated, self.valid]

    def add(self, other: "Row") -> None:
        self.elements += other.elements
        self.generated += other.generated
        self.valid += other.valid

    def figures(self) -> str:
        if not self.elements:
            return "-"
        return f"{100 * self.generated / self.elements:.1f}% / {100 * self.valid / max(self.generated, 1):.1f}%"


class Journal:
    """Finished steps (target, interface, corpus: our Row, the reference's, the failures counted)
    and image checks, appended to a JSON-lines file as each finishes and read back on the next
    run with the same --sample: a run cut short resumes where it stopped, and the table can be
    printed from steps run apart (the image check after a renderer change)."""

    def __init__(self, path: Path | None, sample: int):
        self.path, self.sample = path, sample
        self.steps: dict[tuple, tuple] = {}
        self.images: dict[str, list[dict]] = {}
        if path is None or not path.exists():
            return
        for line in path.read_text().splitlines():
            entry = json.loads(line)
            if entry["sample"] != sample:
                continue
            if "images" in entry:
                self.images[entry["images"]] = [dict(r, psnr=float(r["psnr"])) for r in entry["scored"]]
            else:
                self.steps[tuple(entry["step"])] = (Row(*entry["ours"]), entry["ref"] and Row(*entry["ref"]),
                                                    collections.Counter(entry["reasons"]))

    def _append(self, entry: dict) -> None:
        if self.path is not None:
            with self.path.open("a") as f:
                f.write(json.dumps(dict(entry, sample=self.sample)) + "\n")

    def write(self, step: tuple, mine: Row, theirs: Row | None, reasons: collections.Counter) -> None:
        self.steps[step] = (mine, theirs, reasons)
        self._append({"step": step, "ours": mine.counts(), "ref": theirs and theirs.counts(), "reasons": reasons})

    def write_images(self, target: str, scored: list[dict]) -> None:
        self.images[target] = scored
        self._append({"images": target, "scored": [dict(r, psnr=str(r["psnr"])) for r in scored]})


def check(records_by_doc: dict[Path, list[dict]], target: str, errors, counterparts, reasons, who: str) -> Row:
    """Counts the elements, those generated and those whose every stage the checker accepts."""
    row = Row()
    for doc, records in records_by_doc.items():
        shaders, labels, wgsl, modules = {}, [], {}, {}
        for record in records:
            if record.get("error", {}).get("code") == "no_renderable_element":
                continue
            row.elements += 1
            label = f"{doc.name} {record['element']}"
            if record.get("error", {}).get("code") == "compile_error":  # our vulkan: glslang refused the source
                row.generated += 1
                reasons[f"{who} {target} invalid: {record['error']['message'][:150]} ({doc.name})"] += 1
                continue
            if "error" in record:
                reasons[f"{who} {target} not generated: {record['error']['message'][:110]}"] += 1
                continue
            row.generated += 1
            labels.append(label)
            for stage in ("vertex", "pixel"):
                shaders[f"{label} {stage}"] = (stage, record["stages"][stage])
                if "spirv" in record:
                    modules[f"{label} {stage}"] = base64.b64decode(record["spirv"][stage])
                if record["element"] in counterparts.get(doc, {}):
                    wgsl[f"{label} {stage}"] = counterparts[doc][record["element"]]["stages"][stage]
        # our vulkan record holds the SPIR-V glslang compiled from its source: compiling it again
        # would write the same module (spirv.py), so spirv-val checks the record's
        rejected = spirv_errors(modules) if modules else errors(shaders, wgsl) if counterparts else errors(shaders)
        for message in rejected.values():
            reasons[f"{who} {target} invalid: {message[:150]} ({doc.name})"] += 1
        row.valid += sum(1 for label in labels if not any(k.startswith(label + " ") for k in rejected))
    return row


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--corpus", type=Path, default=SHARED / "corpus")
    parser.add_argument("--targets", default=",".join(TARGETS))
    parser.add_argument("--interfaces", default="complete,specialized")
    parser.add_argument("--no-reference", action="store_true")
    parser.add_argument("--no-images", action="store_true")
    parser.add_argument("--no-conformance", action="store_true",
                        help="generate and validate nothing: the journal's steps only (and the image check)")
    parser.add_argument("--sample", type=int, default=1, help="every Nth document of each corpus")
    parser.add_argument("--size", type=int, default=128, help="image size of the drawn check")
    parser.add_argument("--failures", type=int, default=15)
    parser.add_argument("--journal", type=Path, help="JSON lines: each finished step appended; steps found are reused")
    args = parser.parse_args()
    targets, interfaces = args.targets.split(","), args.interfaces.split(",")
    corpora = documents(args.corpus, args.sample)
    generator = Generator()
    reasons: collections.Counter = collections.Counter()
    rows: dict[tuple, Row] = {}
    journal = Journal(args.journal, args.sample)
    started = time.perf_counter()
    for target in targets:
        try:
            errors = checker_for(target).errors
            errors({})  # Unavailable here, before any work, where the checker looks for its compiler first
        except Unavailable as exc:
            print(f"{target}: not checked: {exc}", flush=True)
            continue
        for interface in interfaces:
            for corpus, docs in corpora.items():
                step = (target, interface, corpus)
                if step not in journal.steps and args.no_conformance:
                    continue
                if step not in journal.steps:
                    found: collections.Counter = collections.Counter()
                    records = {doc: ours(generator, doc, target, interface) for doc in docs}
                    counterparts = {doc: {r["element"]: r for r in ours(generator, doc, "wgsl", interface)
                                          if "error" not in r} for doc in docs} if target == "msl" else {}
                    mine = check(records, target, errors, counterparts, found, "ours")
                    theirs = check(reference(docs, target), target, reference_msl_errors if target == "msl" else errors,
                                   {}, found, "ref") \
                        if interface == "complete" and target in REFERENCE_TARGETS and not args.no_reference else None
                    journal.write(step, mine, theirs, found)
                mine, theirs, found = journal.steps[step]
                rows[(*step, "ours")] = mine
                if theirs:
                    rows[(*step, "ref")] = theirs
                reasons.update(found)
                print(f"  {target} {interface} {corpus}: {mine.figures()}{f' (ref {theirs.figures()})' if theirs else ''}"
                      f" ({time.perf_counter() - started:.0f} s)", file=sys.stderr, flush=True)
    images = {}
    if not args.no_images:
        examples = [str(d) for d in corpora["Examples"]]
        for target in (t for t in targets if t in DRAWN):
            if target not in journal.images:
                journal.write_images(target, compare_images(examples, target, [str(args.corpus)], size=args.size,
                                                            interface="specialized",
                                                            show=lambda line: print(line, file=sys.stderr, flush=True)))
            values = [r["psnr"] for r in journal.images[target]]
            images[target] = (sum(v >= PASS_DB for v in values if not math.isnan(v)), len(values),
                              min((v for v in values if not math.isnan(v)), default=math.nan))

    print(f"| target | interface | corpus | elements | ours generated / validated | reference generated / validated "
          f"| drawn against GL (Examples, specialized) |\n|---|---|---|---:|---:|---:|---|")
    summary = []
    for target in targets:
        total, total_ref = Row(), Row()
        for interface in interfaces:
            for corpus in corpora:
                mine, theirs = rows.get((target, interface, corpus, "ours")), rows.get((target, interface, corpus, "ref"))
                if mine is None:
                    continue
                total.add(mine)
                if theirs:
                    total_ref.add(theirs)
                drawn = ""
                if target in images and interface == "specialized" and corpus == "Examples":
                    passed, count, low = images[target]
                    drawn = f"{passed}/{count} >= {PASS_DB:.0f} dB, min {low:.1f} dB"
                print(f"| {target} | {interface} | {corpus} | {mine.elements} | {mine.figures()} | "
                      f"{theirs.figures() if theirs else '-'} | {drawn} |")
        if total.elements:
            group = f"{target} {total.figures()}" + (f" (ref {total_ref.figures()})" if total_ref.elements else "")
            if target in images:
                group += f" img {images[target][0]}/{images[target][1]}"
            summary.append(group)
    print("\nmost common failures:")
    for reason, count in reasons.most_common(args.failures):
        print(f"  {count:4}  {reason}")
    print(f"({time.perf_counter() - started:.0f} s)")
    print("targets: " + " | ".join(summary))
    return 0


if __name__ == "__main__":
    sys.exit(main())
