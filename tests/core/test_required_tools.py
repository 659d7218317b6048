"""Under CI=true a missing tool fails the test that needs it; elsewhere it skips."""
import os
import subprocess
import sys
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1]
PROBE = """
def test_needs_a_tool(require_tool):
    require_tool("surely-not-an-installed-tool")
"""


def run_probe(tmp_path, ci: str) -> subprocess.CompletedProcess:
    (tmp_path / "conftest.py").write_text((TESTS / "conftest.py").read_text())
    (tmp_path / "test_probe.py").write_text(PROBE)
    env = dict(os.environ, CI=ci, PYTHONPATH=os.pathsep.join([str(TESTS), os.environ.get("PYTHONPATH", "")]))
    return subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", str(tmp_path)],
                          capture_output=True, text=True, env=env, cwd=tmp_path, timeout=120)


def test_a_missing_tool_fails_under_ci(tmp_path):
    run = run_probe(tmp_path, "true")
    assert run.returncode == 1 and "1 failed" in run.stdout and "under CI=true" in run.stdout, run.stdout


def test_a_missing_tool_skips_elsewhere(tmp_path):
    run = run_probe(tmp_path, "false")
    assert run.returncode == 0 and "1 skipped" in run.stdout, run.stdout
