"""`shadergen render` as a user runs it: files out, one-line errors, exit codes, no tracebacks."""
import json
import subprocess
import sys

import numpy as np

from .conftest import DATA, record


def shadergen(*args, cwd):
    return subprocess.run([sys.executable, "-m", "shadergen.cli", "render", *map(str, args)],
                          capture_output=True, text=True, cwd=cwd, timeout=300)


def test_render_a_record_to_png_exr_and_npy(tmp_path):
    rec = record("emission")
    (tmp_path / "rec.json").write_text(json.dumps(rec))
    run = shadergen("--record", "rec.json", "-o", "t.png", "--exr", "t.exr", "--npy", "t.npy",
                    "--size", 64, "--json", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    summary = json.loads(run.stdout)
    assert summary["element"] == "emission" and summary["outputs"] == ["t.png", "t.exr", "t.npy"]
    assert set(summary["timings_ms"]) >= {"compile_link", "first_frame", "frame"}
    assert "compile+link" in run.stderr
    raw = np.load(tmp_path / "t.npy")
    assert raw.shape == (64, 64, 4)
    np.testing.assert_array_equal(raw[32, 32], np.float32([0.25, 0.5, 0.75, 1]))
    assert (tmp_path / "t.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_json_lines_records_are_chosen_by_element(tmp_path):
    lines = [{"document": None, "element": "broken", "error": {"code": "unknown_node", "message": "x"}},
             record("emission")]
    (tmp_path / "recs.jsonl").write_text("\n".join(json.dumps(r) for r in lines) + "\n")
    assert shadergen("--record", "recs.jsonl", "--npy", "a.npy", "--size", 16, cwd=tmp_path).returncode == 0
    run = shadergen("--record", "recs.jsonl", "--element", "broken", "--npy", "b.npy", cwd=tmp_path)
    assert run.returncode == 1 and "unknown_node" in run.stderr


def test_texture_search_paths_and_warnings(tmp_path):
    rec = record("texture")
    rec["document"] = str(tmp_path / "elsewhere" / "doc.mtlx")  # textures are not beside the record
    (tmp_path / "rec.json").write_text(json.dumps(rec))
    run = shadergen("--record", "rec.json", "--npy", "t.npy", "--mesh", "plane", "--size", 32, cwd=tmp_path)
    assert run.returncode == 0 and "warning: texture for image_file" in run.stderr
    run = shadergen("--record", "rec.json", "--npy", "t.npy", "--mesh", "plane", "--size", 32,
                    "--search-path", DATA, cwd=tmp_path)
    assert run.returncode == 0 and "warning" not in run.stderr, run.stderr


def test_bad_inputs_exit_1_with_a_message_and_no_traceback(tmp_path):
    (tmp_path / "bad.json").write_text("{not json")
    rec = record("texture")
    (tmp_path / "tex.json").write_text(json.dumps(rec))
    cases = [
        (["--record", "missing.json", "-o", "x.png"], "invalid_record"),
        (["--record", "bad.json", "-o", "x.png"], "invalid_record"),
        (["--record", "tex.json", "-o", "x.png", "--mesh", DATA / "triangle_no_uv.obj"], "missing_stream"),
        (["--record", "tex.json"], "invalid_request"),                       # no output
        (["--record", "tex.json", "-o", "x.png", "--lights", "none.mtlx"], "invalid_lights"),
        (["--record", "tex.json", "-o", "x.png", "--env", "none.hdr"], "invalid_environment"),
    ]
    for args, code in cases:
        run = shadergen(*args, cwd=tmp_path)
        assert run.returncode == 1, (args, run.stderr)
        assert code in run.stderr and "Traceback" not in run.stderr, (args, run.stderr)
    run = shadergen("--record", "bad.json", "-o", "x.png", "--json", cwd=tmp_path)
    assert json.loads(run.stdout)["error"]["code"] == "invalid_record"


def test_the_command_line_reads_what_the_document_names_and_the_texture_roots(tmp_path):
    import os
    import shutil
    (tmp_path / "Images").mkdir()
    shutil.copy(DATA / "quads.png", tmp_path / "Images" / "quads.png")
    rec = record("texture")
    rec["document"] = str(tmp_path / "Materials" / "doc.mtlx")
    rec["blocks"]["pixel"]["PublicUniforms"][0]["value"] = "../Images/quads.png"  # MaterialX's example layout
    (tmp_path / "rec.json").write_text(json.dumps(rec))
    args = ("--record", "rec.json", "--npy", "t.npy", "--mesh", "plane", "--size", 16)
    run = shadergen(*args, cwd=tmp_path)
    assert run.returncode == 0 and "warning" not in run.stderr, run.stderr
    run = shadergen(*args, "--confine", cwd=tmp_path)
    assert run.returncode == 0 and "outside the allowed folders" in run.stderr, run.stderr
    rec["blocks"]["pixel"]["PublicUniforms"][0]["value"] = "quads.png"  # found only through the roots
    (tmp_path / "rec.json").write_text(json.dumps(rec))
    env = dict(os.environ, SHADERGEN_TEXTURE_ROOTS=f"{tmp_path / 'nowhere'}{os.pathsep}{tmp_path / 'Images'}")
    run = subprocess.run([sys.executable, "-m", "shadergen.cli", "render", *map(str, args), "--confine"],
                         capture_output=True, text=True, cwd=tmp_path, timeout=300, env=env)
    assert run.returncode == 0 and "warning" not in run.stderr, run.stderr


def test_help_gives_defaults_and_an_example():
    run = subprocess.run([sys.executable, "-m", "shadergen.cli", "render", "--help"], capture_output=True, text=True)
    assert run.returncode == 0 and "(default: sphere)" in run.stdout and "examples:" in run.stdout
    assert "SHADERGEN_TEXTURE_ROOTS" in run.stdout
