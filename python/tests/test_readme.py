"""The README's Python example runs as written, and the outputs it names have the shapes
it says."""

import re
from pathlib import Path

README = Path(__file__).resolve().parents[2] / "README.md"


def test_the_readme_example_runs():
    section = README.read_text().split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", section, flags=re.S)
    assert len(blocks) == 1
    namespace = {}
    exec(compile(blocks[0], f"{README}:## Python", "exec"), namespace)
    tri, rec, vor = namespace["tri"], namespace["rec"], namespace["vor"]
    assert tri.triangles.shape[1] == 3 and tri.point_count == 1000
    assert len(vor.cells) == 1000
    assert rec.edges.shape[1] == 2 and namespace["vertices"].shape[1] == 2
