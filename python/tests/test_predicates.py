"""orient2d and incircle give the exact sign, checked against rational arithmetic on
inputs where the floating-point determinant gets the sign wrong."""

import math
import re
from fractions import Fraction

import numpy as np
import pytest

import wdm_crust
from .exact import incircle as exact_incircle
from .exact import orient as exact_orient

ULP = 2.0 ** -53


def rational(p):
    return (Fraction(p[0]), Fraction(p[1]))


def naive_orient(a, b, c):
    det = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])
    return (det > 0) - (det < 0)


def ulp_grid_triples():
    """Kettner et al.: a = (0.5 + i ulp, 0.5 + j ulp) against the diagonal (12, 12)-(24, 24)."""
    return [
        ((0.5 + i * ULP, 0.5 + j * ULP), (12.0, 12.0), (24.0, 24.0))
        for i in range(32)
        for j in range(32)
    ]


def test_orient2d_is_exact_where_floating_point_is_not():
    triples = ulp_grid_triples()
    answers = [wdm_crust.orient2d(*t) for t in triples]
    exact = [exact_orient(*map(rational, t)) for t in triples]
    assert answers == exact
    assert {-1, 0, 1} <= set(answers)  # all three signs occur
    # The test is not vacuous: the plain float64 determinant is wrong on some of them.
    assert sum(naive_orient(*t) != e for t, e in zip(triples, exact)) > 0


def test_orient2d_random_near_collinear():
    rng = np.random.default_rng(4)
    for _ in range(500):
        a, b = rng.random(2) * 100, rng.random(2) * 100
        s = rng.random()
        c = a + s * (b - a)  # on the line up to rounding
        c = c + rng.integers(-3, 4, 2) * np.spacing(c)
        a, b, c = (tuple(p.tolist()) for p in (a, b, c))
        assert wdm_crust.orient2d(a, b, c) == exact_orient(*map(rational, (a, b, c)))


def test_incircle_is_exact_on_nearly_cocircular_points():
    n = 64
    t = 2.0 * math.pi * np.arange(n) / n
    circle = [(math.cos(x), math.sin(x)) for x in t]
    answers, exact = [], []
    for k in range(n):
        a, b, c = circle[k], circle[(k + 7) % n], circle[(k + 23) % n]  # counterclockwise
        for d in circle[:: 5]:
            answers.append(wdm_crust.incircle(a, b, c, d))
            exact.append(exact_incircle(*map(rational, (a, b, c, d))))
    assert answers == exact
    assert {-1, 1} <= set(answers)


def test_incircle_sign_convention_and_exact_zero():
    a, b, c = (0.0, 0.0), (2.0, 0.0), (0.0, 2.0)
    assert wdm_crust.incircle(a, b, c, (1.0, 1.0)) == 1  # inside
    assert wdm_crust.incircle(a, b, c, (2.0, 2.0)) == 0  # on
    assert wdm_crust.incircle(a, b, c, (3.0, 3.0)) == -1  # outside
    assert wdm_crust.incircle(a, c, b, (1.0, 1.0)) == -1  # clockwise: mirrored
    # Lattice points on the circle x² + y² = 65²: exactly cocircular.
    assert wdm_crust.incircle((65, 0), (63, 16), (-33, 56), (-52, -39)) == 0
    assert wdm_crust.orient2d((0, 0), (1, 0), (0, 1)) == 1
    assert wdm_crust.orient2d((0, 0), (0, 1), (1, 0)) == -1


def test_points_may_be_any_pair_of_numbers():
    expected = wdm_crust.orient2d((0.0, 0.0), (1.0, 0.0), (0.0, 1.0))
    assert wdm_crust.orient2d([0, 0], np.array([1.0, 0.0]), np.array([0, 1], np.float32)) == expected


@pytest.mark.parametrize(
    "bad,message",
    [
        ((float("nan"), 0.0), "orient2d: b: coordinate NaN is not a finite number"),
        ((0.0, float("inf")), "orient2d: b: coordinate inf is not a finite number"),
    ],
)
def test_invalid_coordinates_name_the_argument(bad, message):
    with pytest.raises(ValueError, match=message):
        wdm_crust.orient2d((0.0, 0.0), bad, (1.0, 1.0))


@pytest.mark.parametrize("scale", [1e300, 1e-300, 5e-324])
def test_extreme_magnitudes_are_exact_or_refused_naming_the_argument(scale):
    """Refused where the engine's exact predicates do not reach, else the exact sign."""
    triples = [tuple((x * scale, y * scale) for x, y in t) for t in ulp_grid_triples()[:64]]
    for a, b, c in triples:
        try:
            answer = wdm_crust.orient2d(a, b, c)
        except ValueError as error:
            assert re.match(r"orient2d: [abc]: coordinate ", str(error))
        else:
            assert answer == exact_orient(*map(rational, (a, b, c)))


def test_incircle_names_its_fourth_argument():
    with pytest.raises(ValueError, match="incircle: d: "):
        wdm_crust.incircle((0, 0), (1, 0), (0, 1), (float("nan"), 0))


@pytest.mark.parametrize("bad", [(1.0,), (1.0, 2.0, 3.0), "xy", None, 1.0])
def test_non_points_are_a_type_error(bad):
    with pytest.raises(TypeError, match="orient2d: c must be a point"):
        wdm_crust.orient2d((0, 0), (1, 0), bad)
