"""SHADERGEN_TOPOLOGY_SHARING: on (the default), a generation worker records the topology of what it
emits (`top:`), so a value edit is answered from that source; off, nothing is recorded and every
document is emitted, and render workers keep no compiled program. bench/editing.py compares the two."""
import pytest

from service.config import Settings, get_settings
from service.workers.gen_worker import GenerateHandler
from service.workers.render_worker import programs_kept
from service_testing import document


@pytest.fixture
def handler_with(tmp_path, monkeypatch):
    def make(sharing: str) -> GenerateHandler:
        monkeypatch.setenv("SHADERGEN_CACHE", f"sqlite:///{tmp_path / sharing}.sqlite3")
        monkeypatch.setenv("SHADERGEN_TOPOLOGY_SHARING", sharing)
        get_settings.cache_clear()
        return GenerateHandler()
    yield make
    get_settings.cache_clear()


def generate(handler: GenerateHandler, text: str) -> dict:
    message = {"op": "generate", "target": "glsl", "element": None, "interface": "complete"}
    reply, _ = handler(message, text.encode())
    assert "error" not in reply, reply
    return reply


@pytest.mark.parametrize("sharing", ["true", "false"])
def test_the_switch_decides_whether_edits_find_the_source_of_their_topology(handler_with, sharing):
    handler = handler_with(sharing)
    base = document("ramp.mtlx")
    for value in ("0.25", "0.75"):
        generate(handler, base.replace('value="0.5"', f'value="{value}"'))
    topology = handler.generator.prepare(base.encode()).topology_hash
    assert (handler.store.get("top:" + topology) is not None) == (sharing == "true")


def test_render_workers_keep_programs_only_with_sharing():
    assert programs_kept(Settings()) > 0
    assert programs_kept(Settings.from_env({"SHADERGEN_TOPOLOGY_SHARING": "false"})) == 0
