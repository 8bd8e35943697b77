"""A new friction model is one module and one registration.

A toy model in one file (tests/data/toy_model.py) is registered in a fresh
interpreter; the generic tests that run over every registered model then run
it too, and the command line, the web page and the validation list it. Nothing
else in the package changes.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from shared import DATA, ROOT

TOY = DATA / "toy_model.py"
GENERIC = [
    "tests/friction/test_chain.py",
    "tests/friction/test_edges.py",
    "tests/friction/test_properties.py::test_every_model_finite_positive_and_monotonic_in_preload",
]


def _env() -> dict[str, str]:
    return {**os.environ, "BALLSCREW_TEST_EXTRA_MODELS": str(TOY)}


@pytest.mark.slow
def test_the_generic_tests_run_a_new_model_and_pass() -> None:
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "-q",
            "-p",
            "no:cacheprovider",
            "-k",
            "coulomb-toy",
            *GENERIC,
        ],
        cwd=ROOT,
        env=_env(),
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 0, run.stdout[-3000:]
    # Each generic test ran the toy: every parametrized test over the models, not none.
    passed = int(run.stdout.strip().splitlines()[-1].split()[0])
    assert passed >= 10, run.stdout[-500:]


SCRIPT = """
import json, runpy, sys
runpy.run_path(sys.argv[1])
from ballscrew.cli import main
from ballscrew.web.service import model_choices
from ballscrew.study.validation import score
print(json.dumps({
    "web": [m["name"] for m in model_choices()],
    "validation": sorted({row.model for row in score(["coulomb-toy"])}),
}))
main(["models"])
"""


def test_the_command_line_the_web_page_and_the_validation_list_a_new_model() -> None:
    run = subprocess.run(
        [sys.executable, "-c", SCRIPT, str(TOY)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
    )
    first, _, rest = run.stdout.partition("\n")
    assert run.returncode == 0, run.stderr[-3000:]
    listed = json.loads(first)
    assert "coulomb-toy" in listed["web"]
    assert listed["validation"] == ["coulomb-toy"]
    assert "coulomb-toy" in rest and "constant coefficient" in rest
