"""Reconstruct a noisy outline with a hole and plot it with matplotlib.

    python python/examples/noisy_outline.py [OUTPUT.png]

Samples a five-petal flower (about 2.6 units across) with a round hole at random
positions, adds Gaussian noise (sigma = 0.001), shuffles the points (the reconstruction
needs no order), then draws the points, the reconstructed curves, the medial axis and the
points left on no curve.
"""

import sys

import matplotlib

matplotlib.use("Agg")  # write a file; no display needed
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection

import wdm_crust


def noisy_flower(rng):
    t = rng.uniform(0.0, 2.0 * np.pi, 300)
    r = 1.0 + 0.3 * np.cos(5.0 * t)
    outline = np.c_[r * np.cos(t), r * np.sin(t)]
    s = rng.uniform(0.0, 2.0 * np.pi, 80)
    hole = np.c_[0.3 * np.cos(s) + 0.1, 0.3 * np.sin(s)]
    points = np.vstack([outline, hole]) + rng.normal(0.0, 0.001, (380, 2))
    return rng.permutation(points)


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else "noisy_outline.png"
    points = noisy_flower(np.random.default_rng(2))
    rec = wdm_crust.reconstruct(points)  # WDM_CRUST, peeling for the hole, pruned medial axis
    print(rec)

    fig, ax = plt.subplots(figsize=(7, 7))
    ax.scatter(points[:, 0], points[:, 1], s=4, color="0.55", label="points", zorder=1)
    labelled = set()
    for curve in rec.curves:
        # A closed loop lists each point once: repeat the first to draw the closing edge.
        xy = np.vstack([curve.coords, curve.coords[:1]]) if curve.closed else curve.coords
        kind = "closed curve" if curve.closed else "open chain"
        color = "tab:red" if curve.closed else "tab:purple"
        ax.plot(xy[:, 0], xy[:, 1], color=color, lw=1.4, zorder=3,
                label=None if kind in labelled else kind)
        labelled.add(kind)
    vertices, edges = rec.medial_axis
    ax.add_collection(LineCollection(vertices[edges], colors="tab:green", lw=0.9,
                                     label="medial axis", zorder=2))
    lost = points[rec.unassigned]
    ax.scatter(lost[:, 0], lost[:, 1], s=30, facecolors="none", edgecolors="tab:blue",
               label=f"unassigned ({len(lost)})", zorder=4)
    ax.set_aspect("equal")
    ax.set_title(f"wdm_crust.reconstruct: {len(points)} shuffled noisy points")
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
