"""Fault tests: a real `shadergen serve` on 127.0.0.1 per module, whose processes are killed and
whose files are corrupted while it runs. The helpers that start servers are the service tests'."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "service"))
