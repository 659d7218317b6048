"""Generation is a function of its input: the same documents generated in two orders in one
process give byte-identical records, in every target. Everything memoised along the way (the
library's typed templates, the code passes' rewrites, printed library items) is memoised by what
determines it, never by what came first."""
import json
from pathlib import Path

from shadergen.api import Generator

ROOT = Path(__file__).resolve().parents[2]
DOCUMENTS = [ROOT / "tests" / "golden" / n for n in ("glass.mtlx", "standard_surface_coated.mtlx")] + \
    sorted((ROOT / "examples").glob("*.mtlx")) + \
    [ROOT / "tests" / "service" / "documents" / n for n in ("metal.mtlx", "ramp.mtlx", "textured.mtlx")]
REQUESTS = [(d, target, interface) for d in DOCUMENTS for target in ("glsl", "essl", "wgsl")
            for interface in ("complete", "specialized")]


def records(generator: Generator, requests) -> dict:
    out = {}
    for document, target, interface in requests:
        for record in generator.records(document, target=target, interface=interface, all=True):
            record.pop("timings_ms", None)
            out[(str(document), target, interface, record.get("element"))] = json.dumps(record, sort_keys=True)
    return out


def test_two_orders_in_one_process_give_byte_identical_records():
    generator = Generator()
    forward = records(generator, REQUESTS)
    backward = records(generator, REQUESTS[::-1])
    fresh = records(Generator(), REQUESTS[len(REQUESTS) // 2:] + REQUESTS[:len(REQUESTS) // 2])
    assert len(forward) >= len(REQUESTS)
    failed = [key for key, r in forward.items() if '"error"' in r]
    assert len(failed) < len(forward) // 10, failed
    for key, record in forward.items():
        assert backward[key] == record, key
        assert fresh[key] == record, key
