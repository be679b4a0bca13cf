"""The real point sets the repository carries (tests/data), by their path relative to it."""

from pathlib import Path

DATA = Path(__file__).resolve().parents[2] / "tests" / "data"
SUFFIXES = {".txt", ".p2d", ".xy", ".xym", ".gtn", ".node", ".csv"}


def real_point_files():
    """(name, path) of every real point file, the fuzz regressions and the license left out;
    a missing data directory fails rather than skips."""
    files = sorted(
        p
        for p in DATA.rglob("*")
        if p.is_file()
        and p.suffix in SUFFIXES
        and p.name != "GPL-3.0.txt"
        and p.relative_to(DATA).parts[0] != "regressions"
    )
    assert len(files) >= 25, f"the real point sets are missing: {DATA}"
    return [(str(p.relative_to(DATA)), p) for p in files]
