"""`shadergen render --batch` (issue 23): a library's thumbnails in one process, one program per
topology, an error record for each broken document beside the others' thumbnails."""
import json
import os
import signal
import subprocess
import sys

from processes import children, cmdline


def material(shader: str, tint: str, mat: str, color: str) -> str:
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  <multiply name="{tint}" type="color3">
    <input name="in1" type="color3" value="{color}" /><input name="in2" type="float" value="0.8" />
  </multiply>
  <surface_unlit name="{shader}" type="surfaceshader"><input name="emission_color" type="color3" nodename="{tint}" /></surface_unlit>
  <surfacematerial name="{mat}" type="material"><input name="surfaceshader" type="surfaceshader" nodename="{shader}" /></surfacematerial>
</materialx>
"""


def shadergen(*args, cwd):
    return subprocess.run([sys.executable, "-m", "shadergen.cli", "render", *map(str, args)],
                          capture_output=True, text=True, cwd=cwd, timeout=600)


def library(folder):
    """Three materials of one topology under different names and values (one in a subfolder, of
    the same file name as another), a document that is not XML, and one with an unknown node."""
    (folder / "sub").mkdir(parents=True)
    (folder / "red.mtlx").write_text(material("S_red", "T_red", "Red", "0.9, 0.1, 0.1"))
    (folder / "green.mtlx").write_text(material("S_green", "T_green", "Green", "0.1, 0.9, 0.1"))
    (folder / "sub" / "red.mtlx").write_text(material("shader", "tint", "Blue", "0.1, 0.1, 0.9"))
    (folder / "broken.mtlx").write_text('<materialx version="1.39"><multiply')
    (folder / "unknown.mtlx").write_text('<?xml version="1.0"?><materialx version="1.39"><frobnicate name="f" '
                                         'type="color3"/><output name="o" type="color3" nodename="f"/></materialx>')


def results(folder) -> dict[str, dict]:
    lines = (folder / "results.jsonl").read_text().splitlines()
    return {json.loads(line)["document"].rsplit("lib/", 1)[1]: json.loads(line) for line in lines}


def test_a_folder_is_one_program_per_topology_and_an_error_record_per_broken_document(tmp_path):
    library(tmp_path / "lib")
    run = shadergen("--batch", "lib", "-o", "out", "--size", 32, cwd=tmp_path)
    assert run.returncode == 1, run.stderr  # some documents failed
    assert "Traceback" not in run.stderr
    assert "5 documents, 5 materials: 3 thumbnails, 2 errors; 1 programs compiled, 2 reused" in run.stderr
    got = results(tmp_path / "out")
    assert got["broken.mtlx"]["error"]["code"] == "invalid_document"
    assert got["unknown.mtlx"]["error"]["code"] == "unknown_node"
    for document, element in (("red.mtlx", "Red"), ("green.mtlx", "Green"), ("sub/red.mtlx", "Blue")):
        assert got[document]["element"] == element and "error" not in got[document]
    pngs = {document: (tmp_path / got[document]["png"]).read_bytes() for document in ("red.mtlx", "green.mtlx",
                                                                                   "sub/red.mtlx")}
    assert got["sub/red.mtlx"]["png"] == "out/sub/red/Blue.png"  # documents of one name keep apart
    assert len(set(pngs.values())) == 3 and all(p[:8] == b"\x89PNG\r\n\x1a\n" for p in pngs.values())
    # a material drawn with a program compiled for another is the image of its own render
    for document in ("green.mtlx", "sub/red.mtlx"):
        single = shadergen(f"lib/{document}", "--interface", "complete", "-o", "single.png", "--size", 32,
                           cwd=tmp_path)
        assert single.returncode == 0, single.stderr
        assert (tmp_path / "single.png").read_bytes() == pngs[document]


def test_a_list_names_the_documents_and_a_clean_batch_succeeds(tmp_path):
    library(tmp_path / "lib")
    (tmp_path / "lib" / "list.txt").write_text("# the good ones\ngreen.mtlx\n\nsub/red.mtlx\n")
    run = shadergen("--batch", "lib/list.txt", "-o", "out", "--size", 16, "--json", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    printed = [json.loads(line) for line in run.stdout.splitlines()]
    assert [r["element"] for r in printed] == ["Green", "Blue"] and [r["program_reused"] for r in printed] == [False, True]


def test_a_batch_of_nothing_is_one_error_line(tmp_path):
    (tmp_path / "empty").mkdir()
    run = shadergen("--batch", "empty", "-o", "out", cwd=tmp_path)
    assert run.returncode == 1 and "invalid_request" in run.stderr and "Traceback" not in run.stderr
    run = shadergen("--batch", "missing.txt", "-o", "out", cwd=tmp_path)
    assert run.returncode == 1 and "cannot read the batch list" in run.stderr


def _generator_children(pid: int) -> list[int]:
    """The process's children that run the generator (multiprocessing's spawned workers, not its
    resource tracker)."""
    return [child for child in children(pid) if "spawn_main" in cmdline(child)]


def test_the_generator_child_killed_mid_batch_loses_no_material(tmp_path):
    """The documents are generated in a child process ahead of the drawing; killed, it takes no
    document with it: what it had not answered is generated by the drawing process."""
    lib = tmp_path / "lib"
    lib.mkdir()
    for i in range(24):
        (lib / f"m{i:02d}.mtlx").write_text(material(f"S{i}", f"T{i}", f"M{i}", f"0.{i % 10}, 0.5, 0.5"))
    proc = subprocess.Popen([sys.executable, "-m", "shadergen.cli", "render", "--batch", "lib", "-o", "out",
                             "--size", "16"], cwd=tmp_path, stderr=subprocess.PIPE, text=True)
    killed, lines = None, []
    for line in proc.stderr:  # a progress line every tenth of the batch: drawing has begun
        lines.append(line)
        if killed is None and "documents," in line:
            children = _generator_children(proc.pid)
            if children:
                killed = children[0]
                os.kill(killed, signal.SIGKILL)
    proc.wait(timeout=600)
    stderr = "".join(lines)
    assert killed is not None, "the batch ended before its generator child could be killed"
    assert proc.returncode == 0, stderr
    assert "24 documents, 24 materials: 24 thumbnails, 0 errors" in stderr
    lines = [json.loads(line) for line in (tmp_path / "out" / "results.jsonl").read_text().splitlines()]
    assert [r["element"] for r in lines] == [f"M{i}" for i in range(24)]
