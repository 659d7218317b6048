"""Property-based requests from openapi.yaml against the live server: whatever schemathesis
sends, no 5xx, and every answer has a documented status, media type and schema. Bounded in
examples per operation; the server is the session's live `shadergen serve`."""
from pathlib import Path

import schemathesis
import schemathesis_hooks  # noqa: F401 (registers the USD body serializer here too)
import yaml
from hypothesis import HealthCheck, settings
from schemathesis.checks import not_a_server_error
from schemathesis.specs.openapi.checks import (content_type_conformance, response_schema_conformance,
                                               status_code_conformance)

CHECKS = [not_a_server_error, status_code_conformance, content_type_conformance, response_schema_conformance]
# the committed contract, which test_openapi.py keeps equal to what the server serves
schema = schemathesis.openapi.from_dict(yaml.safe_load((Path(__file__).parents[2] / "openapi.yaml").read_text()))


@schema.parametrize()
@settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
def test_no_server_errors(case, server):
    case.call_and_validate(base_url=server.url, checks=CHECKS, timeout=60)


def test_bounded_run_with_all_checks(server, tmp_path):
    """Every phase schemathesis has (coverage with negative data, fuzzing, stateful) and every
    check, with positive_data_acceptance replaced by its sound form (schemathesis_hooks.py): no
    5xx, and no request the schema allows refused by the server's own validation."""
    import os
    import subprocess
    import sys

    here = Path(__file__).parent
    run = subprocess.run(
        [sys.executable, "-m", "schemathesis.cli", "run", str(here.parents[1] / "openapi.yaml"), "--url", server.url,
         "--checks", "all", "--exclude-checks", "positive_data_acceptance", "--max-examples", "20", "--seed", "1",
         "--continue-on-failure", "--report-dir", str(tmp_path)],
        cwd=here, env={**os.environ, "SCHEMATHESIS_HOOKS": "schemathesis_hooks"},
        capture_output=True, text=True, timeout=600,
    )
    assert run.returncode == 0, run.stdout[-6000:] + run.stderr[-2000:]
    assert " passed" in run.stdout and "failures" not in run.stdout.split("SUMMARY")[-1]
