import json
import subprocess
import sys

from .conftest import doc


def run(*args):
    return subprocess.run([sys.executable, "-m", "shadergen.cli", *args], capture_output=True, text=True)


def test_generate_writes_stage_files(tmp_path):
    src = tmp_path / "d.mtlx"
    src.write_text(doc('<sin name="s" type="float"/><output name="o" type="float" nodename="s"/>'))
    p = run("generate", str(src), "--out", str(tmp_path / "out"))
    assert p.returncode == 0, p.stderr
    rec = json.loads(p.stdout)
    assert rec["element"] == "o" and set(rec["blocks"]) == {"vertex", "pixel"}
    assert (tmp_path / "out" / "o.frag").read_text() == rec["stages"]["pixel"]
    assert (tmp_path / "out" / "o.vert").exists() and (tmp_path / "out" / "o.json").exists()


def test_errors_are_records_and_exit_1(tmp_path):
    bad = tmp_path / "bad.mtlx"
    bad.write_text("<materialx><oops")
    p = run("generate", str(bad))
    assert p.returncode == 1 and "Traceback" not in p.stderr
    rec = json.loads(p.stdout)
    assert rec["error"]["code"] == "invalid_document" and rec["error"]["where"].startswith(str(bad))


def test_document_without_renderable_element_is_an_error_record(tmp_path):
    empty = tmp_path / "defs.mtlx"
    empty.write_text(doc('<nodedef name="ND_x" node="x"><output name="out" type="float"/></nodedef>'))
    p = run("generate", str(empty))
    assert p.returncode == 1 and "Traceback" not in p.stderr
    rec = json.loads(p.stdout)
    assert rec["error"]["code"] == "no_renderable_element" and rec["element"] is None
