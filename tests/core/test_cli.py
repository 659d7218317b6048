import json
import os
import subprocess
import sys

import pytest

from .conftest import doc


def run(*args, stdin: str | None = None):
    return subprocess.run([sys.executable, "-m", "shadergen.cli", *args], capture_output=True, text=True,
                          input=stdin, timeout=300)


SIN = doc('<sin name="s" type="float"/><output name="o" type="float" nodename="s"/>')


def test_generate_writes_stage_files(tmp_path):
    src = tmp_path / "d.mtlx"
    src.write_text(doc('<sin name="s" type="float"/><output name="o" type="float" nodename="s"/>'))
    p = run("generate", str(src), "--out", str(tmp_path / "out"))
    assert p.returncode == 0, p.stderr
    rec = json.loads(p.stdout)
    assert rec["element"] == "o" and set(rec["blocks"]) == {"vertex", "pixel"}
    assert (tmp_path / "out" / "d" / "o.glsl.frag").read_text() == rec["stages"]["pixel"]
    assert (tmp_path / "out" / "d" / "o.glsl.vert").exists() and (tmp_path / "out" / "d" / "o.glsl.json").exists()


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


def test_out_keeps_every_document_element_and_target_apart(tmp_path):
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
    (tmp_path / "a" / "one.mtlx").write_text(SIN)
    (tmp_path / "a" / "two.mtlx").write_text(SIN.replace("sin", "cos"))
    out = tmp_path / "out"
    for target in ("glsl", "essl"):
        p = run("generate", "--target", target, "--out", str(out), str(tmp_path / "a" / "one.mtlx"),
                str(tmp_path / "a" / "two.mtlx"))
        assert p.returncode == 0, p.stdout
    written = sorted(str(f.relative_to(out)) for f in out.rglob("*.frag"))
    assert written == ["one/o.essl.frag", "one/o.glsl.frag", "two/o.essl.frag", "two/o.glsl.frag"]
    assert "cos(" in (out / "two" / "o.glsl.frag").read_text() and "sin(" in (out / "one" / "o.glsl.frag").read_text()
    (tmp_path / "b" / "one.mtlx").write_text(SIN.replace("sin", "tan"))  # same name, another folder: refused
    p = run("generate", "--out", str(tmp_path / "again"), str(tmp_path / "a" / "one.mtlx"), str(tmp_path / "b" / "one.mtlx"))
    records = [json.loads(line) for line in p.stdout.splitlines()]
    assert p.returncode == 1 and records[1]["error"]["code"] == "output_collision"
    assert "sin(" in (tmp_path / "again" / "one" / "o.glsl.frag").read_text()


def test_dash_reads_the_document_from_stdin():
    p = run("generate", "-", stdin=SIN)
    assert p.returncode == 0, p.stdout
    assert "sin(" in json.loads(p.stdout)["stages"]["pixel"]


@pytest.mark.parametrize("option, value, listed", [("--interface", "full", "complete, reduced"),
                                                   ("--target", "mdl", "essl, glsl")])
def test_unsupported_options_list_the_valid_values(tmp_path, option, value, listed):
    (tmp_path / "d.mtlx").write_text(SIN)
    rec = json.loads(run("generate", option, value, str(tmp_path / "d.mtlx")).stdout)
    assert rec["error"]["code"] == f"unsupported_{option[2:]}" and listed in rec["error"]["message"]


def test_help_gives_defaults_and_examples():
    p = run("generate", "--help")
    assert p.returncode == 0 and "(default: glsl)" in p.stdout and "(default: complete)" in p.stdout
    assert "examples:" in p.stdout and "shadergen generate -" in p.stdout


@pytest.mark.parametrize("command", ["generate", "render", "serve", "worker"])
def test_every_option_of_every_command_is_explained(command):
    import argparse
    import importlib

    from shadergen.cli import SUBCOMMANDS
    parser = argparse.ArgumentParser()
    importlib.import_module(SUBCOMMANDS[command][0]).add_arguments(parser)
    unexplained = [a.dest for a in parser._actions if not a.help]
    assert not unexplained, f"{command}: {unexplained} have no help"


def test_generate_specialized_keeps_the_inputs_named(tmp_path):
    src = tmp_path / "d.mtlx"
    src.write_text(doc('<add name="a" type="float"><input name="in1" type="float" value="1"/>'
                       '<input name="in2" type="float" value="2"/></add>'
                       '<sin name="s" type="float"><input name="in" type="float" nodename="a"/></sin>'
                       '<output name="o" type="float" nodename="s"/>'))
    folded = json.loads(run("generate", str(src), "--interface", "specialized", "--names", "document").stdout)
    assert "float s_out = 0.14112;" in folded["stages"]["pixel"] and folded["passes"]["fold"] == 2  # sin(1 + 2)
    p = run("generate", str(src), "--interface", "specialized", "--keep", "a/in1, a/in2")
    kept = json.loads(p.stdout)
    assert [v["path"] for v in kept["blocks"]["pixel"]["PublicUniforms"]] == ["a/in1", "a/in2"]
    uniform = {v["path"]: v["name"] for v in kept["blocks"]["pixel"]["PublicUniforms"]}  # bound by the listing
    assert f"n0_out = {uniform['a/in1']} + {uniform['a/in2']};" in kept["stages"]["pixel"]


def test_a_cold_generate_imports_no_more_than_it_uses(tmp_path):
    """Pipelines start `generate` once per document, so its imports are part of every answer:
    not the renderer or the web stack, not pathlib or shutil (a few milliseconds each, more
    than the work of a small document), and not hashlib, which starts OpenSSL (shadergen/digest.py).
    Run without `site`, so that only the package's own imports count, not what an installation's
    start-up files load."""
    src = tmp_path / "d.mtlx"
    src.write_text(SIN)
    code = ("import sys; from shadergen.cli import main; code = main(sys.argv[1:]); "
            "print(' '.join(sorted(sys.modules)), file=sys.stderr); sys.exit(code)")
    p = subprocess.run([sys.executable, "-S", "-c", code, "generate", str(src), "--out", str(tmp_path / "out")],
                       capture_output=True, text=True, timeout=300,
                       env={"PYTHONPATH": os.pathsep.join(p for p in sys.path if p)})
    assert p.returncode == 0, p.stderr
    assert json.loads(p.stdout)["element"] == "o"
    loaded = set(p.stderr.split())
    assert "shadergen.api" in loaded
    assert not loaded & {"pathlib", "shutil", "hashlib", "_hashlib", "numpy", "pydantic", "fastapi", "moderngl",
                         "shadergen.render"}
