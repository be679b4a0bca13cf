"""Shared fixtures: the command-line binary the package is compared with, and a summary of
how scipy.spatial.Delaunay fared on the adversarial inputs (shown, never asserted)."""

import json
import subprocess
from pathlib import Path

import numpy as np
import pytest

from .scipy_report import VERDICTS

REPO = Path(__file__).resolve().parents[2]
CLI = REPO / "target" / "release" / "wdm-crust"


@pytest.fixture(scope="session")
def cli():
    """Runs `wdm-crust SUBCOMMAND` on points and returns its parsed JSON output."""
    if not CLI.is_file():
        pytest.fail(
            f"{CLI} is missing: these tests compare the package with the command line; "
            "build it first with `cargo build --release` in the repository root",
            pytrace=False,
        )

    def run(subcommand, points, *args):
        # repr() of a float is its shortest round-trip form, which the CLI parses back to
        # the same float64.
        text = "".join(f"{x!r} {y!r}\n" for x, y in np.asarray(points, dtype=float).tolist())
        done = subprocess.run(
            [str(CLI), subcommand, *args],
            input=text.encode(),
            capture_output=True,
            check=False,
        )
        if done.returncode != 0:
            raise AssertionError(f"wdm-crust {subcommand} failed: {done.stderr.decode()}")
        return json.loads(done.stdout)

    return run


def pytest_terminal_summary(terminalreporter):
    if not VERDICTS:
        return
    failed = [name for name, verdict in VERDICTS if verdict != "exact Delaunay"]
    terminalreporter.section("scipy.spatial.Delaunay on the adversarial inputs")
    for name, verdict in VERDICTS:
        terminalreporter.write_line(f"{name:<28} {verdict}")
    terminalreporter.write_line(
        f"scipy: {len(failed)} of {len(VERDICTS)} not an exact Delaunay "
        "triangulation of all the points; wdm_crust: exact on every input it accepts (asserted)"
    )
