"""Writes the app's OpenAPI document as YAML: `python -m service.openapi > openapi.yaml`.
tests/service/test_openapi.py fails when the committed file and the app disagree."""
import json
import sys

import yaml


def openapi_document() -> dict:
    from .main import create_app

    # through JSON, so the comparison sees what a client fetching /openapi.json sees
    return json.loads(json.dumps(create_app().openapi()))


def main() -> None:
    yaml.safe_dump(openapi_document(), sys.stdout, sort_keys=False, allow_unicode=True, width=100)


if __name__ == "__main__":
    main()
