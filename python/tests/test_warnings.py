"""Warnings and duplicates of a reconstruction, as the command line's JSON has them."""

import numpy as np

import wdm_crust


def circle(cx, n=200):
    t = np.arange(n) * 2 * np.pi / n
    return np.column_stack([cx + np.cos(t), np.sin(t)])


def test_curves_one_spacing_apart_are_too_close():
    points = np.vstack([circle(0.0), circle(2.0 + 2 * np.pi / 200)])
    rec = wdm_crust.reconstruct(points)
    codes = [code for code, _ in rec.warnings]
    assert codes == ["curves-too-close"]
    assert "sample more densely" in rec.warnings[0][1]


def test_a_clean_circle_has_nothing_to_say():
    rec = wdm_crust.reconstruct(circle(0.0))
    assert rec.warnings == []
    assert rec.duplicates.shape == (0, 2) and rec.duplicates.dtype == np.int64


def test_a_scatter_is_called_one():
    rng = np.random.default_rng(7)
    rec = wdm_crust.reconstruct(rng.random((1000, 2)))
    codes = [code for code, _ in rec.warnings]
    assert "most-unassigned" in codes and "scatter" in codes


def test_duplicates_pair_each_repeat_with_its_first_occurrence():
    points = circle(0.0, 64)
    points = np.vstack([points, points[[5, 9, 5]]])
    rec = wdm_crust.reconstruct(points)
    assert rec.duplicates.tolist() == [[64, 5], [65, 9], [66, 5]]
    assert rec.duplicates.tolist() == wdm_crust.triangulate(points).duplicates.tolist()
