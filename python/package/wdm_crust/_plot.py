"""`wdm_crust.plot`: a matplotlib picture of a reconstruction. matplotlib is imported only
when a picture is drawn, so the package works without it."""

import numpy as np

# Colours of the command line's SVG picture, so that both read the same way.
_POINT = "#111111"
_UNASSIGNED = "#8c8c8c"
_CLOSED = "#d62728"
_OPEN = "#7b3fb5"
_MEDIAL = "#2ca02c"


def _pyplot():
    try:
        import matplotlib.pyplot as pyplot
    except ImportError as error:
        raise ImportError(
            "wdm_crust.plot draws with matplotlib, which is not installed: "
            "pip install matplotlib"
        ) from error
    return pyplot


def plot(rec, ax=None, *, points=True, medial_axis=True, legend=True):
    """Draws a reconstruction with matplotlib: the input points, the closed curves (red),
    the open chains (purple), the points on no curve (grey rings) and the medial axis
    (green), on equal axes.

    Args:
        rec: a Reconstruction (from `wdm_crust.reconstruct`).
        ax: the matplotlib Axes to draw on; None (the default) draws on a new figure's.
        points: draw the input points (small dots) and the unassigned ones (rings).
        medial_axis: draw the medial axis.
        legend: add a legend naming what is drawn, with the counts.

    Returns:
        The Axes drawn on.

    Raises:
        ImportError: matplotlib is not installed (`pip install matplotlib`).

    A closed curve is drawn closed (its first point repeated at the end); curves use their
    `coords`, the fitted positions with `smooth=True`. Nothing is drawn for what is empty.
    """
    pyplot = _pyplot()
    from matplotlib.collections import LineCollection

    if ax is None:
        _, ax = pyplot.subplots()
    xy = rec.points
    n = len(xy)
    closed = [c for c in rec.curves if c.closed]
    chains = [c for c in rec.curves if not c.closed]
    if medial_axis:
        vertices, segments = rec.medial_axis
        if len(segments):
            lines = vertices[segments]
            finite = np.isfinite(lines).all(axis=(1, 2))
            ax.add_collection(
                LineCollection(
                    lines[finite],
                    colors=_MEDIAL,
                    linewidths=1.1,
                    label=f"medial axis ({len(segments)} segments)",
                    zorder=1,
                )
            )
    for k, curve in enumerate(closed):
        ring = np.vstack([curve.coords, curve.coords[:1]])
        ax.plot(
            ring[:, 0],
            ring[:, 1],
            color=_CLOSED,
            linewidth=1.4,
            label=f"closed curves ({len(closed)})" if k == 0 else None,
            zorder=2,
        )
    for k, chain in enumerate(chains):
        ax.plot(
            chain.coords[:, 0],
            chain.coords[:, 1],
            color=_OPEN,
            linewidth=1.4,
            label=f"open chains ({len(chains)})" if k == 0 else None,
            zorder=2,
        )
    if points and n:
        size = 4.0 if n <= 2000 else 1.0
        ax.scatter(
            xy[:, 0], xy[:, 1], s=size, color=_POINT, linewidths=0, label=f"points ({n})", zorder=3
        )
        unassigned = rec.unassigned
        if len(unassigned):
            ax.scatter(
                xy[unassigned, 0],
                xy[unassigned, 1],
                s=28,
                facecolors="none",
                edgecolors=_UNASSIGNED,
                linewidths=1.0,
                label=f"on no curve ({len(unassigned)})",
                zorder=4,
            )
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    if legend and ax.get_legend_handles_labels()[0]:
        ax.legend(loc="best", fontsize="small", framealpha=0.85)
    return ax
