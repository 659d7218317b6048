"""Conformance of the C-family targets (hlsl, slang, msl): every renderable element of every
document under the given folders, generated for each target and interface, each stage checked by
its target's checker (shadergen/targets/<name>/check.py). With `--oracle`, the reference
generator's own output for the same targets (../shared/oracle/mx_oracle.py) through the same
checkers. (Until bench/targets.py holds every target's table.)

    .venv/bin/python bench/cfamily.py ../shared/corpus/resources/Materials/TestSuite/stdlib \
        ../shared/corpus/resources/Materials/TestSuite/pbrlib ../shared/corpus/resources/Materials/Examples \
        [--targets hlsl,slang,msl] [--interfaces complete,specialized] [--oracle] [--failures N]

Prints a row per target and interface (elements, generated %, validated % of generated) and
ends with one line `cfamily: <target> <interface> gen% / valid% | ...`.
"""
import argparse
import collections
import importlib
import json
import os
import subprocess
from pathlib import Path

from shadergen.api import generate_file

ORACLE_PYTHON = os.path.expanduser("~/.cache/mx-oracle/venv/bin/python")
ORACLE = Path(__file__).resolve().parents[2] / "shared" / "oracle" / "mx_oracle.py"


def ours(doc: Path, target: str, interface: str):
    return generate_file(str(doc), target=target, all=True, interface=interface)


def reference(doc: Path, target: str, interface: str):
    run = subprocess.run([ORACLE_PYTHON, str(ORACLE), str(doc), "--target", target, "--all", "--interface", interface],
                         capture_output=True, text=True)
    if run.returncode != 0 and not run.stdout.strip():
        return [{"element": doc.name, "error": {"code": "oracle_failed", "message": run.stderr.strip()[-200:]}}]
    return [json.loads(line) for line in run.stdout.splitlines() if line.strip()]


def measure(docs, target: str, interface: str, generate, reasons: collections.Counter) -> dict:
    errors = importlib.import_module(f"shadergen.targets.{target}.check").errors
    elements = generated = valid = 0
    for doc in docs:
        shaders, labels, wgsl = {}, [], {}
        # MSL is cross-checked against naga's MSL of our WGSL for the same element (msl/check.py)
        counterparts = {r["element"]: r for r in ours(doc, "wgsl", interface) if "error" not in r} \
            if target == "msl" else {}
        for rec in generate(doc, target, interface):
            if rec.get("error", {}).get("code") == "no_renderable_element":
                continue
            elements += 1
            if "error" in rec:
                reasons[f"{target} {interface} not generated: {rec['error']['message'][:100]}"] += 1
                continue
            generated += 1
            label = f"{doc.name} {rec['element']}"
            labels.append(label)
            for stage in ("vertex", "pixel"):
                shaders[f"{label} {stage}"] = (stage, rec["stages"][stage])
                if rec["element"] in counterparts:
                    wgsl[f"{label} {stage}"] = counterparts[rec["element"]]["stages"][stage]
        rejected = errors(shaders, wgsl) if target == "msl" else errors(shaders)
        for message in rejected.values():
            reasons[f"{target} {interface} invalid: {message[:140]} ({doc.name})"] += 1
        valid += sum(1 for label in labels if not any(k.startswith(label + " ") for k in rejected))
    return {"elements": elements, "generated": 100 * generated / max(elements, 1),
            "valid": 100 * valid / max(generated, 1)}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("folders", nargs="+", type=Path)
    parser.add_argument("--targets", default="hlsl,slang,msl")
    parser.add_argument("--interfaces", default="complete,specialized")
    parser.add_argument("--oracle", action="store_true", help="the reference generator's output instead of ours")
    parser.add_argument("--failures", type=int, default=12)
    args = parser.parse_args()
    docs = sorted(d for folder in args.folders for d in folder.rglob("*.mtlx"))
    reasons: collections.Counter = collections.Counter()
    summary = []
    for target in args.targets.split(","):
        for interface in args.interfaces.split(","):
            row = measure(docs, target, interface, reference if args.oracle else ours, reasons)
            print(f"{target:6} {interface:12} elements {row['elements']:4}  generated {row['generated']:6.2f} %  "
                  f"validated {row['valid']:6.2f} %", flush=True)
            summary.append(f"{target} {interface} {row['generated']:.1f}% / {row['valid']:.1f}%")
    for reason, count in reasons.most_common(args.failures):
        print(f"  {count:4}  {reason}")
    print(("cfamily oracle: " if args.oracle else "cfamily: ") + " | ".join(summary))


if __name__ == "__main__":
    main()
