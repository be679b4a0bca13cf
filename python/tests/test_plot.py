"""`wdm_crust.plot` draws with matplotlib, without a display (the Agg backend), and says
what to install without matplotlib."""

import subprocess
import sys

import numpy as np
import pytest

import wdm_crust
from .samples import SAMPLES


def test_plot_renders_a_png(tmp_path):
    matplotlib = pytest.importorskip("matplotlib", reason="matplotlib is not installed")
    matplotlib.use("Agg")
    import matplotlib.pyplot as pyplot

    points = np.vstack([SAMPLES["nested circles"](), SAMPLES["open arc"](), [[2.2, -2.0]]])
    rec = wdm_crust.reconstruct(points)
    assert any(c.closed for c in rec.curves) and any(not c.closed for c in rec.curves)
    assert len(rec.unassigned) and len(rec.medial_axis[1])
    ax = wdm_crust.plot(rec)
    labels = ax.get_legend_handles_labels()[1]
    closed = sum(c.closed for c in rec.curves)
    assert f"closed curves ({closed})" in labels
    assert f"open chains ({len(rec.curves) - closed})" in labels
    assert f"on no curve ({len(rec.unassigned)})" in labels
    assert f"points ({len(points)})" in labels
    assert any(label.startswith("medial axis") for label in labels)
    out = tmp_path / "rec.png"
    ax.figure.savefig(out, dpi=80)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    pyplot.close(ax.figure)
    # Without the points on top, the curves' colours are there to be counted.
    ax = wdm_crust.plot(rec, points=False, legend=False)
    ax.figure.savefig(out, dpi=100)
    image = pyplot.imread(out)[..., :3]
    for colour in ("#d62728", "#7b3fb5", "#2ca02c"):  # closed, open, medial axis
        rgb = np.array(matplotlib.colors.to_rgb(colour))
        assert (np.abs(image - rgb).max(axis=2) < 0.2).sum() > 50, colour
    pyplot.close(ax.figure)
    # On given axes, and for a result with nothing in it.
    figure, axes = pyplot.subplots(1, 2)
    assert wdm_crust.plot(rec, axes[0], points=False, legend=False) is axes[0]
    assert wdm_crust.plot(wdm_crust.reconstruct(np.zeros((0, 2))), axes[1]) is axes[1]
    pyplot.close(figure)


def test_without_matplotlib_the_error_says_what_to_install():
    code = (
        "import sys; sys.modules['matplotlib'] = None\n"
        "import wdm_crust\n"
        "rec = wdm_crust.reconstruct([[0, 0], [1, 0], [0, 1]])\n"
        "try:\n"
        "    wdm_crust.plot(rec)\n"
        "except ImportError as e:\n"
        "    print(e)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, check=True)
    assert "pip install matplotlib" in done.stdout.decode()
