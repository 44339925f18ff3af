"""Issue 14, items 9-11: input sizes bounded before the work grows (one degree limit everywhere), no silent
non-finite answers, messages that name the real cause and carry no control characters."""

import math

import pytest

import ratbez
from conftest import raises_naming


def test_item9_degree_and_point_limits_refuse_before_the_work():
    # 10^5 control points took 57 s before the degree refusal; now the count is checked first.
    error = raises_naming("points", ratbez.BezierCurve, [(float(i), 0.0) for i in range(100000)])
    assert "26" in str(error) and "25" in str(error)
    ratbez.BezierCurve([(float(i), math.sin(i)) for i in range(26)])  # degree 25, the limit, is accepted
    # A degree-1 NURBS profile past the point limit (10^6 points revolved for 400 s): refused at once.
    n = 100_001
    knots = [0.0] + [i / (n - 1) for i in range(n)] + [1.0]
    raises_naming("points", ratbez.NurbsCurve, 1, knots, [(1.0 + (i % 2), i * 1e-6) for i in range(n)])
    # One degree limit for bases, curves and matrices (bezier_to_power_matrix(1100) held 505,083 non-finite entries).
    raises_naming("n", ratbez.bezier_to_power_matrix, 1100)
    raises_naming("n", ratbez.bezier_to_power_matrix, 26)
    assert all(math.isfinite(x) for row in ratbez.bezier_to_power_matrix(25) for x in row)
    raises_naming("n", ratbez.bernstein, 0, 10**6, 0.5)
    raises_naming("degree", ratbez.NurbsCurve, 30, [0.0] * 31 + [1.0] * 31, [(float(i), 0.0) for i in range(31)])


def test_item10_extreme_weights_give_the_true_point():
    # weights 1e308 gave point(0.5) = (inf, 0.5, 0); the curve is the line from (1, 0) to (1, 1).
    curve = ratbez.BezierCurve([(1, 0), (1, 1)], weights=[1e308, 1e308])
    assert curve.point(0.5) == pytest.approx((1.0, 0.5, 0.0), abs=1e-15)
    assert curve.weights == [1e308, 1e308]  # given back exactly
    nurbs = ratbez.NurbsCurve(1, [0, 0, 1, 1], [(1, 0), (1, 1)], weights=[1e308, 1e308])
    assert nurbs.point(0.5) == pytest.approx((1.0, 0.5, 0.0), abs=1e-15)
    tiny = ratbez.BezierCurve([(1, 0), (1, 1)], weights=[1e-300, 1e-300])
    assert tiny.point(0.25) == pytest.approx((1.0, 0.25, 0.0), abs=1e-15)


def test_item10_tiny_domain_is_finite():
    # A NURBS domain [0, 5e-324] gave NaN: the basis is built from ratios of knot differences now.
    curve = ratbez.NurbsCurve(1, [0.0, 0.0, 5e-324, 5e-324], [(0, 0), (1, 1)])
    assert curve.point(0.0) == (0.0, 0.0, 0.0)
    assert curve.point(5e-324) == (1.0, 1.0, 0.0)


def test_item10_high_derivative_orders_are_bounded_or_finite():
    arc = ratbez.BezierCurve([(1, 0), (1, 1), (0, 1)], weights=[1, 1, 2])
    raises_naming("order", arc.derivative, 0.3, 200)  # gave NaN after O(k^3) work
    for order in (1, 5, 20, 100):
        value = arc.derivative(0.3, order)
        assert all(math.isfinite(x) for x in value), (order, value)


def test_item11_messages_name_the_cause():
    raises_naming("p", ratbez.bspline_basis, 0, 2**31 - 1, [0.0, 1.0], 0.5)  # overflowed building its message
    error = raises_naming("radius", ratbez.sphere, 1e308)
    assert "collapse" not in str(error)
    error = raises_naming("radius", ratbez.sphere, 1.0, (1e17, 0, 0))
    assert "inward" not in str(error)
    corners = [(1, 0, 0), (2, 0, 0), (2, 0, 1), (1, 0, 1)]
    square = [ratbez.BezierCurve([corners[k], corners[(k + 1) % 4]]) for k in range(4)]
    assert ratbez.revolve(square, (0, 0, 0), (0, 0, 1), 1e-3).volume() > 0
    error = raises_naming("angle", ratbez.revolve, square, (0, 0, 0), (0, 0, 1), 1e-12)
    assert "thickness" in str(error)


def test_item11_messages_carry_no_control_characters():
    with pytest.raises(ratbez.Error) as info:
        ratbez.write_text_file("/nonexistent-\x1b[2J-folder/a.txt", "x")
    text = str(info.value)
    assert "\x1b" not in text and "\\x1b" in text
    assert all(c.isprintable() for c in text), text
