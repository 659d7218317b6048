"""openapi.yaml is the HTTP contract: it must equal what the app serves."""
from pathlib import Path

import yaml

from service.openapi import openapi_document

ROOT = Path(__file__).resolve().parents[2]


def test_committed_openapi_matches_the_app():
    committed = yaml.safe_load((ROOT / "openapi.yaml").read_text())
    assert committed == openapi_document(), "regenerate it: python -m service.openapi > openapi.yaml"


def test_live_openapi_matches_the_file(client):
    committed = yaml.safe_load((ROOT / "openapi.yaml").read_text())
    assert client.get("/openapi.json").json() == committed
