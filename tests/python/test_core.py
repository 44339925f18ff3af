"""Curves, surfaces and bases through Python: the worked examples Ex1.14 and Ex1.15 of the source
text, properties that hold for every input, and the types the contract promises."""
import math

import pytest

import ratbez
from conftest import close

# Ex1.13 / Ex1.14: the rational quadratic arc P = (1,0), (1,1), (0,1), w = 1, 1, 2 (2D points: z = 0).
ARC_POINTS = [(1, 0), (1, 1), (0, 1)]
ARC_WEIGHTS = [1, 1, 2]

# Ex1.15: the cylindrical patch; P^w_{i,0} = (1,1,0,1), (1,1,1,1), (2,0,2,2) and P^w_{i,1} with x = -1.
CYLINDER_NET = [[(1, 1, 0), (-1, 1, 0)], [(1, 1, 1), (-1, 1, 1)], [(1, 0, 1), (-1, 0, 1)]]
CYLINDER_WEIGHTS = [[1, 1], [1, 1], [2, 2]]


def test_bernstein_values_and_partition_of_unity():
    assert close(ratbez.bernstein(1, 3, 0.5), 0.375)
    assert close(ratbez.bernstein(0, 2, 0.25), 0.5625)
    assert ratbez.bernstein(-1, 3, 0.5) == 0.0
    assert ratbez.bernstein(4, 3, 0.5) == 0.0
    for u in (0.0, 0.1, 0.37, 0.5, 0.9, 1.0):
        assert close(sum(ratbez.bernstein(i, 5, u) for i in range(6)), 1.0)
    assert close(ratbez.all_bernstein(3, 0.5), [0.125, 0.375, 0.375, 0.125])


def test_bspline_basis_cox_de_boor():
    knots = [0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5]  # degree 2, the standard worked example
    assert close(ratbez.bspline_basis(2, 2, knots, 2.5), 1 / 8)
    assert close(ratbez.bspline_basis(3, 2, knots, 2.5), 6 / 8)
    assert close(ratbez.bspline_basis(4, 2, knots, 2.5), 1 / 8)
    assert ratbez.bspline_basis(0, 2, knots, 2.5) == 0.0
    for u in (0.0, 0.5, 1.0, 2.2, 3.9, 4.0, 4.7, 5.0):
        assert close(sum(ratbez.bspline_basis(i, 2, knots, u) for i in range(8)), 1.0)
    # {0,0,0,1,1,1} turns the B-spline basis into the Bernstein basis (001).
    for i in range(3):
        assert close(ratbez.bspline_basis(i, 2, [0, 0, 0, 1, 1, 1], 0.3), ratbez.bernstein(i, 2, 0.3))
    # Keyword names of the contract; a tuple and a generator-free numpy-like sequence both work.
    assert close(ratbez.bspline_basis(i=1, p=1, knots=(0, 0, 1, 1), u=0.25), 0.25)


def test_bezier_to_power_matrix_exercise_1_14():
    assert ratbez.bezier_to_power_matrix(2) == [[1, 0, 0], [-2, 2, 0], [1, -2, 1]]


def test_ex1_14_rational_arc_point():
    c = ratbez.BezierCurve(ARC_POINTS, weights=ARC_WEIGHTS)
    assert c.degree == 2 and c.is_rational
    assert c.points == [(1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0)]
    assert c.weights == [1.0, 1.0, 2.0]
    assert close(c.point(0.5), (3 / 5, 4 / 5, 0))
    assert close(c.point_de_casteljau(0.5), (3 / 5, 4 / 5, 0))
    assert close(c.homogeneous_point(0.5), (3 / 4, 1, 0, 5 / 4))
    table = c.de_casteljau_table(0.5)  # Table 1.4
    assert close(table[1][0], (1, 0.5, 0, 1)) and close(table[1][1], (0.5, 1.5, 0, 1.5))
    assert close(table[2][0], (3 / 4, 1, 0, 5 / 4))
    for k in range(11):
        x, y, z = c.point(k / 10)
        assert close(x * x + y * y, 1.0) and z == 0.0
    # Starting speed twice the end speed (end of Ex1.14).
    d0, d1 = c.derivative(0.0), c.derivative(1.0, order=1)
    assert close(math.hypot(*d0), 2 * math.hypot(*d1))


def test_bezier_curve_operations():
    c = ratbez.BezierCurve([(0, 0, 0), (1, 2, 0), (3, 2, 1), (4, 0, 0)])
    assert not c.is_rational and c.weights == [1.0] * 4
    left, right = c.split(0.3)
    assert isinstance(left, ratbez.BezierCurve) and isinstance(right, ratbez.BezierCurve)
    assert close(left.point(1.0), c.point(0.3)) and close(right.point(0.5), c.point(0.65))
    e = c.elevate()
    assert e.degree == 4
    for u in (0.0, 0.2, 0.77, 1.0):
        assert close(e.point(u), c.point(u))
        assert close(c.reversed().point(u), c.point(1 - u))
    assert close(c.derivative(0.0), (3, 6, 0))  # n (P1 - P0)
    assert close(c.derivative(u=0.0, order=2), (6 * (3 - 2 + 0), 6 * (2 - 4 + 0), 6 * 1))
    assert len(c.derivatives(0.5, 3)) == 4


def test_ex1_15_cylindrical_patch():
    s = ratbez.BezierSurface(CYLINDER_NET, weights=CYLINDER_WEIGHTS)
    assert (s.degree_u, s.degree_v) == (2, 1) and s.is_rational
    for method in (s.point, s.point_basis, s.point_u_first, s.point_v_first, s.point_one_step):
        assert close(method(0.5, 0.5), (0, 3 / 5, 4 / 5))
    for u in (0.0, 0.3, 0.5, 1.0):
        for v in (0.0, 0.25, 1.0):
            x, y, z = s.point(u, v)
            assert close(y * y + z * z, 1.0) and close(x, 1 - 2 * v)
            n = s.normal(u, v)
            assert close(abs(n[1] * y + n[2] * z), 1.0) and close(n[0], 0.0)
    arc = s.isocurve_v(0.5)  # the circular arc in the yz plane
    assert isinstance(arc, ratbez.BezierCurve) and arc.degree == 2
    assert close(arc.point(0.5), (0, 3 / 5, 4 / 5))
    line = s.isocurve_u(0.5)  # a straight segment parallel to x
    assert line.degree == 1 and close(line.point(0.0)[1:], line.point(1.0)[1:])
    assert close(s.derivative(0.5, 0.5), s.derivative(0.5, 0.5, du=1, dv=0))
    assert close(s.derivative(0.5, 0.5, du=0, dv=1), (-2, 0, 0))
    assert len(s.derivatives(0.5, 0.5, 2)) == 3


def test_nurbs_curve_and_surface():
    c = ratbez.NurbsCurve(2, [0, 0, 0, 1, 1, 1], ARC_POINTS, weights=ARC_WEIGHTS)
    assert c.degree == 2 and c.knots == [0, 0, 0, 1, 1, 1] and c.domain == (0.0, 1.0)
    assert c.weights == [1.0, 1.0, 2.0] and c.points[2] == (0.0, 1.0, 0.0) and c.is_rational
    assert close(c.point(0.5), (3 / 5, 4 / 5, 0))
    assert close(c.derivative(0.5), ratbez.BezierCurve(ARC_POINTS, ARC_WEIGHTS).derivative(0.5))
    assert close(c.derivative(0.5, order=2), ratbez.BezierCurve(ARC_POINTS, ARC_WEIGHTS).derivative(0.5, 2))
    refined = c.insert_knot(0.5)
    assert len(refined.knots) == 7 and close(refined.point(0.3), c.point(0.3))
    assert len(refined.bezier_segments()) == 2

    poly = ratbez.NurbsCurve(degree=1, knots=[0, 0, 1, 2, 2], points=[(0, 0), (1, 0), (1, 1)])
    assert poly.domain == (0.0, 2.0) and not poly.is_rational
    assert close(poly.point(1.5), (1, 0.5, 0))

    s = ratbez.NurbsSurface(2, 1, [0, 0, 0, 1, 1, 1], [0, 0, 1, 1], CYLINDER_NET, weights=CYLINDER_WEIGHTS)
    assert (s.degree_u, s.degree_v) == (2, 1)
    assert s.domain == ((0.0, 1.0), (0.0, 1.0))
    assert s.knots_u == [0, 0, 0, 1, 1, 1] and s.knots_v == [0, 0, 1, 1]
    assert s.weights == [[1, 1], [1, 1], [2, 2]] and s.points[2][1] == (-1.0, 0.0, 1.0)
    assert close(s.point(0.5, 0.5), (0, 3 / 5, 4 / 5))
    assert close(s.derivative(0.5, 0.5, du=0, dv=1), (-2, 0, 0))
    assert close(s.normal(u=0.5, v=0.5), s.normal(0.5, 0.5))
    assert isinstance(s.isocurve_u(0.5), ratbez.NurbsCurve) and isinstance(s.isocurve_v(0.5), ratbez.NurbsCurve)


def test_numpy_inputs_are_sequences():
    np = pytest.importorskip("numpy")
    c = ratbez.BezierCurve(np.array(ARC_POINTS, dtype=float), weights=np.array(ARC_WEIGHTS))
    assert close(c.point(np.float64(0.5)), (3 / 5, 4 / 5, 0))
    n = ratbez.NurbsCurve(np.int64(2), np.array([0, 0, 0, 1, 1, 1.0]), ARC_POINTS)
    assert n.degree == 2
