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


def points_text(points):
    """The points as a point file: repr() of a float is its shortest round-trip form, which
    the CLI parses back to the same float64."""
    return "".join(f"{x!r} {y!r}\n" for x, y in np.asarray(points, dtype=float).tolist())


@pytest.fixture(scope="session")
def cli_text():
    """Runs `wdm-crust ARGS...` (on `points` as standard input, if given) and returns its
    standard output as text; a failing run fails the test with its message."""
    if not CLI.is_file():
        pytest.fail(
            f"{CLI} is missing: these tests compare the package with the command line; "
            "build it first with `cargo build --release` in the repository root",
            pytrace=False,
        )

    def run(*args, points=None):
        done = subprocess.run(
            [str(CLI), *map(str, args)],
            input=None if points is None else points_text(points).encode(),
            capture_output=True,
            check=False,
        )
        if done.returncode != 0:
            raise AssertionError(f"wdm-crust {' '.join(map(str, args))} failed: {done.stderr.decode()}")
        return done.stdout.decode()

    return run


@pytest.fixture(scope="session")
def cli(cli_text):
    """Runs `wdm-crust SUBCOMMAND` on points and returns its parsed JSON output."""

    def run(subcommand, points, *args):
        return json.loads(cli_text(subcommand, *args, points=points))

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
