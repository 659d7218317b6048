"""The web material editor: static ES modules under /editor/ (no build step), and `/` leading there."""
from pathlib import Path

from fastapi import APIRouter
from fastapi.responses import RedirectResponse
from fastapi.staticfiles import StaticFiles

EDITOR_DIR = Path(__file__).resolve().parents[1] / "static" / "editor"

router = APIRouter(include_in_schema=False)


@router.get("/")
async def home() -> RedirectResponse:
    return RedirectResponse("/editor/")


def editor_files() -> StaticFiles:
    """The editor's files, mounted at /editor (index.html for the folder itself)."""
    return StaticFiles(directory=EDITOR_DIR, html=True)
