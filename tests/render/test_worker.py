"""A renderer in a spawned worker process keeps rendering and reports errors as RenderError."""
import numpy as np
import pytest

from shadergen.render import RenderError
from shadergen.render.worker import RenderWorker, lp_threads_for

from .conftest import record


def test_spawned_worker_renders_and_survives_errors():
    with RenderWorker(lp_threads=1) as worker:
        first = worker.render(record("emission"), size=32)
        np.testing.assert_array_equal(first.rgba[16, 16], np.float32([0.25, 0.5, 0.75, 1]))
        with pytest.raises(RenderError) as caught:
            worker.render({"element": "x", "target": "osl", "stages": {"vertex": "a", "pixel": "b"}})
        assert caught.value.code == "unsupported_target"
        again = worker.render(record("emission"), size=32)  # same process, program cached
        assert again.timings_ms["compile_link"] == 0.0


def test_lp_threads_share_the_cores():
    assert lp_threads_for(1) >= 1 and lp_threads_for(10_000) == 1


def test_a_job_past_its_timeout_kills_the_worker_and_the_next_job_gets_a_fresh_one():
    slow = record("emission")
    slow["stages"]["pixel"] = slow["stages"]["pixel"].replace(
        "out1 = vec4(u_color, 1.0);",
        "float x = u_color.r; for (int i = 0; i < 100000000; ++i) { x = sin(x) + u_color.g; } out1 = vec4(x);")
    with RenderWorker(lp_threads=1) as worker:
        with pytest.raises(RenderError) as caught:
            worker.render(slow, size=64, timeout=2.0)
        assert caught.value.code == "timeout"
        result = worker.render(record("emission"), size=16, timeout=120)
        assert result.rgba[8, 8, 3] == 1.0
