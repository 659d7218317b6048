"""Fixtures every test folder shares: the tools a test needs (see required_tools.py)."""
import pytest

from required_tools import require_renderer, tool_path


@pytest.fixture
def require_tool():
    """`require_tool("dpkg")` -> the tool's path; skips, or fails under CI=true, when it is missing."""
    return tool_path


@pytest.fixture
def glslang_validator() -> str:
    return tool_path("glslangValidator")


@pytest.fixture(scope="session")
def renderer_required() -> None:
    require_renderer()
