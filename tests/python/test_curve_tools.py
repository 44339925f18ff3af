"""Issue 26, the curve tools every NURBS library has: ratbez.interpolate passes through its points to 1e-12 and
equals The NURBS Book's A9.1 computed independently here with numpy and ratbez.bspline_basis; end tangents,
closed curves; ratbez.approximate meets its tolerance with the fewest control points; interpolate_surface
(A9.4); curve.length() of a circle is 2 pi r to 1e-12 and parameter_at_length inverts it; elevated() keeps
curves and surfaces."""
import math

import numpy as np
import pytest

import ratbez
from conftest import close, raises_naming
from test_contract import keywords


def test_keywords_follow_the_contract():
    assert keywords(ratbez.interpolate) == ["points", "degree", "parameterization", "tangents", "closed"]
    assert keywords(ratbez.approximate) == ["points", "tolerance", "degree"]
    assert keywords(ratbez.interpolate_surface) == ["grid", "degree_u", "degree_v"]
    assert keywords(ratbez.NurbsCurve.length) == ["u0", "u1"]
    assert keywords(ratbez.NurbsCurve.parameter_at_length) == ["s"]
    assert keywords(ratbez.NurbsCurve.elevated) == ["times"]
    assert keywords(ratbez.NurbsSurface.elevated) == ["times_u", "times_v"]
    assert keywords(ratbez.BezierCurve.length) == ["u0", "u1"]


def random_walk(rng, count):
    return np.cumsum(rng.uniform(-2, 2, size=(count, 3)), axis=0)


def textbook_a91(points, degree, exponent):
    """A9.1 written out: parameters (Eq. 9.5/9.6/9.3), averaged knots (Eq. 9.8), the dense collocation
    matrix by Cox-de Boor (ratbez.bspline_basis), numpy's solver."""
    q = np.asarray(points, dtype=float)
    steps = np.linalg.norm(np.diff(q, axis=0), axis=1) ** exponent
    t = np.concatenate([[0.0], np.cumsum(steps) / steps.sum()])
    t[-1] = 1.0
    n = len(q) - 1
    knots = [0.0] * (degree + 1) + [sum(t[j:j + degree]) / degree for j in range(1, n - degree + 1)] + [1.0] * (degree + 1)
    a = np.array([[ratbez.bspline_basis(j, degree, knots, tk) for j in range(n + 1)] for tk in t])
    return t, knots, np.linalg.solve(a, q)


@pytest.mark.parametrize("parameterization, exponent", [("chord", 1.0), ("centripetal", 0.5), ("uniform", 0.0)])
def test_interpolate_passes_through_its_points_and_equals_a91(parameterization, exponent):
    rng = np.random.default_rng(26)
    for degree in (1, 2, 3, 5):
        points = random_walk(rng, 12)
        curve = ratbez.interpolate(points, degree=degree, parameterization=parameterization)
        t, knots, control = textbook_a91(points, degree, exponent)
        assert curve.degree == degree and set(curve.weights) == {1.0}
        assert np.allclose(curve.knots, knots, rtol=0, atol=1e-15)
        size = np.abs(points).max()
        assert np.abs(np.array(curve.points) - control).max() <= 1e-12 * size
        reproduced = curve.evaluate(t)
        assert np.abs(reproduced - points).max() <= 1e-12 * size


def test_interpolate_end_tangents_and_closed_curves():
    points = [(0, 0), (1, 2), (3, 2), (4, 0)]
    chord = sum(math.dist(a, b) for a, b in zip(points, points[1:]))
    curve = ratbez.interpolate(points, 3, tangents=((0, 1), (0, -2)))
    assert len(curve.points) == 6
    assert close(curve.derivative(0.0), (0, chord, 0), 1e-12)
    assert close(curve.derivative(1.0), (0, -chord, 0), 1e-12)
    start_only = ratbez.interpolate(points, 2, tangents=((1, 1), None))
    assert close(start_only.derivative(0.0), (chord / math.sqrt(2), chord / math.sqrt(2), 0), 1e-12)
    # Closed: through every point and back to the first, C2 at the seam for a cubic.
    ring = [(math.cos(a) * (2 + 0.3 * math.cos(3 * a)), math.sin(a) * 2, 0.2 * math.sin(a))
            for a in np.linspace(0, 2 * math.pi, 9)[:-1]]
    loop = ratbez.interpolate(ring, 3, "centripetal", closed=True)
    assert loop.points[0] == loop.points[-1] == (ring[0][0], ring[0][1], ring[0][2])
    for order in (1, 2):
        assert close(loop.derivative(0.0, order), loop.derivative(1.0, order), 1e-9)
    # A closed interpolant of points on a circle is close to the circle.
    on_circle = [(2 * math.cos(a), 2 * math.sin(a)) for a in np.linspace(0, 2 * math.pi, 25)[:-1]]
    approx_circle = ratbez.interpolate(on_circle, 3, closed=True)
    radii = np.linalg.norm(approx_circle.evaluate(np.linspace(0, 1, 200))[:, :2], axis=1)
    assert np.abs(radii - 2).max() < 1e-4
    assert math.isclose(approx_circle.length(), 4 * math.pi, rel_tol=1e-5)


def test_interpolate_refuses_what_it_cannot_do():
    raises_naming("points", ratbez.interpolate, [(0, 0), (1, 0), (2, 1)], 3)
    raises_naming("points", ratbez.interpolate, [(0, 0), (0, 0), (2, 1)], 1)
    raises_naming("degree", ratbez.interpolate, [(0, 0), (1, 0)], 0)
    raises_naming("parameterization", ratbez.interpolate, [(0, 0), (1, 0)], 1, "arc")
    raises_naming("tangents", ratbez.interpolate, [(0, 0), (1, 0), (2, 1)], 2, tangents=((0, 0), None))
    raises_naming("tangents", ratbez.interpolate, [(0, 0), (1, 0), (2, 1)], 2, tangents=((1, 0),))
    raises_naming("tangents", ratbez.interpolate, [(0, 0), (1, 0), (2, 1)], 2, tangents=((1, 0), None), closed=True)


def test_approximate_meets_the_tolerance_with_few_control_points():
    x = np.linspace(0, 4 * math.pi, 401)
    points = np.column_stack([x, np.sin(x), 0.1 * np.cos(3 * x)])
    for tolerance in (1e-2, 1e-4):
        curve = ratbez.approximate(points, tolerance)
        t = np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(points, axis=0), axis=1))])
        t /= t[-1]
        assert np.linalg.norm(curve.evaluate(t) - points, axis=1).max() <= tolerance
        assert len(curve.points) < 100
        assert curve.points[0] == tuple(points[0]) and curve.points[-1] == tuple(points[-1])
    raises_naming("tolerance", ratbez.approximate, points, 0.0)
    raises_naming("points", ratbez.approximate, [(0, 0), (1, 1)], 1e-3)


def test_interpolate_surface_passes_through_its_grid():
    u = np.linspace(0, 1, 6)
    v = np.linspace(0, 2, 5) ** 1.5
    grid = [[(a, b, math.sin(3 * a) * math.cos(b)) for b in v] for a in u]
    surface = ratbez.interpolate_surface(grid, 3, 3)
    assert (surface.degree_u, surface.degree_v) == (3, 3)
    # Parameters: the columns' (rows') chord parameters averaged (Eq. 9.5 with the book's averaging).
    g = np.asarray(grid)
    tu = np.mean([np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(g[:, j], axis=0), axis=1))]) /
                  np.linalg.norm(np.diff(g[:, j], axis=0), axis=1).sum() for j in range(len(v))], axis=0)
    tv = np.mean([np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(g[i], axis=0), axis=1))]) /
                  np.linalg.norm(np.diff(g[i], axis=0), axis=1).sum() for i in range(len(u))], axis=0)
    values = surface.evaluate(tu, tv)
    assert np.abs(values - g).max() <= 1e-12
    raises_naming("grid", ratbez.interpolate_surface, grid, 6, 3)


def test_length_of_a_circle_and_its_inverse():
    for r in (0.001, 2.0, 1234.5):
        c = ratbez.circle(r, center=(1, 2, 3), normal=(1, 1, 1))
        assert math.isclose(c.length(), 2 * math.pi * r, rel_tol=1e-12)
        assert math.isclose(c.length(0.25, 0.75), math.pi * r, rel_tol=1e-12)
        assert math.isclose(c.parameter_at_length(math.pi * r / 2), 0.25, rel_tol=1e-12)
    arc = ratbez.BezierCurve([(1, 0), (1, 1), (0, 1)], weights=[1, 1, 2])  # a quarter circle (Ex1.14)
    assert math.isclose(arc.length(), math.pi / 2, rel_tol=1e-12)
    assert math.isclose(arc.length(0.0, arc.parameter_at_length(0.3)), 0.3, rel_tol=1e-12)
    raises_naming("s", ratbez.circle(1).parameter_at_length, 7.0)
    raises_naming("u1", ratbez.circle(1).length, 0.0, 2.0)


def test_elevated_keeps_curves_and_surfaces():
    c = ratbez.circle(3)
    e = c.elevated(2)
    assert e.degree == 4
    us = np.linspace(0, 1, 101)
    assert np.abs(np.linalg.norm(e.evaluate(us), axis=1) - 3).max() <= 1e-14 * 3
    assert np.abs(e.evaluate(us) - c.evaluate(us)).max() <= 1e-14 * 3
    s = ratbez.sphere(2).faces[0].surface
    se = s.elevated(1, 2)
    assert (se.degree_u, se.degree_v) == (s.degree_u + 1, s.degree_v + 2)
    (u0, u1), (v0, v1) = s.domain
    us, vs = np.linspace(u0, u1, 17), np.linspace(v0, v1, 13)
    assert np.abs(se.evaluate(us, vs) - s.evaluate(us, vs)).max() <= 1e-14 * 2
    raises_naming("times", c.elevated, -1)
