"""Bad input raises ratbez.Error (a ValueError) whose message names the offending argument."""
import math

import pytest

import ratbez
from conftest import raises_naming

P3 = [(0, 0), (1, 1), (2, 0)]
NET = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
NAN = math.nan


def test_error_is_a_value_error():
    assert issubclass(ratbez.Error, ValueError)
    assert ratbez.Error.__name__ == "Error"
    with pytest.raises(ValueError):
        ratbez.BezierCurve([])


@pytest.mark.parametrize(
    "argument, args, kwargs",
    [
        ("points", ([],), {}),
        ("points", ("abc",), {}),
        ("points", (None,), {}),
        ("points", (5,), {}),
        ("points[1]", ([(0, 0), (1,)],), {}),
        ("points[1]", ([(0, 0), (1, 2, 3, 4)],), {}),
        ("points[1]", ([(0, 0), ("a", 1)],), {}),
        ("points", ([(0, 0), (NAN, 1)],), {}),
        ("weights", (P3,), {"weights": [1, 1]}),
        ("weights", (P3,), {"weights": [1, 0, 1]}),
        ("weights", (P3,), {"weights": [1, -2, 1]}),
        ("weights", (P3,), {"weights": [1, NAN, 1]}),
        ("weights", (P3,), {"weights": "abc"}),
    ],
)
def test_bezier_curve_rejects(argument, args, kwargs):
    raises_naming(argument, ratbez.BezierCurve, *args, **kwargs)


@pytest.mark.parametrize(
    "argument, args, kwargs",
    [
        ("net", ([],), {}),
        ("net", ([[]],), {}),
        ("net", ([[(0, 0), (1, 0)], [(0, 1)]],), {}),   # ragged rows
        ("net[0]", ([5],), {}),
        ("net", ([[(0, 0), (NAN, 0)], [(0, 1), (1, 1)]],), {}),
        ("weights", (NET,), {"weights": [[1, 1]]}),
        ("weights", (NET,), {"weights": [[1, 1], [1, -1]]}),
    ],
)
def test_bezier_surface_rejects(argument, args, kwargs):
    raises_naming(argument, ratbez.BezierSurface, *args, **kwargs)


@pytest.mark.parametrize(
    "argument, args, kwargs",
    [
        ("degree", (2.5, [0, 0, 0, 1, 1, 1], P3), {}),
        ("degree", ("2", [0, 0, 0, 1, 1, 1], P3), {}),
        ("degree", (-1, [0, 0, 0, 1, 1, 1], P3), {}),
        ("knots", (2, [0, 0, 1, 1], P3), {}),                 # wrong count
        ("knots", (2, [0, 0, 0, 1, 0.5, 1], P3), {}),         # decreasing
        ("knots", (2, [0, 0, 0, NAN, 1, 1], P3), {}),
        ("knots", (2, None, P3), {}),
        ("points", (2, [0, 0, 0, 1, 1, 1], []), {}),
        ("weights", (2, [0, 0, 0, 1, 1, 1], P3), {"weights": [1, 1]}),
        ("weights", (2, [0, 0, 0, 1, 1, 1], P3), {"weights": [1, -1, 1]}),
    ],
)
def test_nurbs_curve_rejects(argument, args, kwargs):
    raises_naming(argument, ratbez.NurbsCurve, *args, **kwargs)


@pytest.mark.parametrize(
    "argument, args, kwargs",
    [
        ("degree_u", (1.5, 1, [0, 0, 1, 1], [0, 0, 1, 1], NET), {}),
        ("degree_v", (1, None, [0, 0, 1, 1], [0, 0, 1, 1], NET), {}),
        ("knots_u", (1, 1, [0, 0, 0, 1, 1], [0, 0, 1, 1], NET), {}),
        ("knots_v", (1, 1, [0, 0, 1, 1], [1, 1, 0, 0], NET), {}),
        ("net", (1, 1, [0, 0, 1, 1], [0, 0, 1, 1], []), {}),
        ("weights", (1, 1, [0, 0, 1, 1], [0, 0, 1, 1], NET), {"weights": [[1, 1], [1, 0]]}),
    ],
)
def test_nurbs_surface_rejects(argument, args, kwargs):
    raises_naming(argument, ratbez.NurbsSurface, *args, **kwargs)


@pytest.mark.parametrize(
    "argument, call",
    [
        ("radius", lambda: ratbez.circle(-1.0)),
        ("radius", lambda: ratbez.circle(NAN)),
        ("normal", lambda: ratbez.circle(1.0, normal=(0, 0, 0))),
        ("center", lambda: ratbez.circle(1.0, center=(1, 2, 3, 4))),
        ("radius", lambda: ratbez.arc(0.0, 0, 90)),
        ("radius", lambda: ratbez.cylinder(0.0, 1.0)),
        ("height", lambda: ratbez.cylinder(1.0, -1.0)),
        ("axis", lambda: ratbez.cylinder(1.0, 1.0, axis=(0, 0, 0))),
        ("center", lambda: ratbez.cylinder(1.0, 1.0, center="origin")),
        ("height", lambda: ratbez.cone(1.0, 0.5, 0.0)),
        ("radius", lambda: ratbez.sphere(0.0)),
        ("center", lambda: ratbez.sphere(1.0, center=(1,))),
        ("radius", lambda: ratbez.torus(-3.0, 1.0)),
        ("axis", lambda: ratbez.torus(3.0, 1.0, axis=(NAN, 0, 1))),
        ("profile", lambda: ratbez.revolve("a circle")),
        ("profile", lambda: ratbez.revolve([])),
        ("profile[1]", lambda: ratbez.revolve([ratbez.line_segment((1, 0), (2, 0)), 42])),
        ("axis_dir", lambda: ratbez.revolve(ratbez.circle(1, center=(3, 0, 0), normal=(0, 1, 0)), axis_dir=(0, 0, 0))),
        ("profile", lambda: ratbez.extrude(None, (0, 0, 1), 1.0)),
        ("direction", lambda: ratbez.extrude(ratbez.circle(1.0), (0, 0), 1.0)),
        ("tolerance", lambda: ratbez.sphere(1.0).tessellate(0.0)),
        ("tolerance", lambda: ratbez.sphere(1.0).tessellate(-1.0)),
        ("triangles", lambda: ratbez.Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 3)])),
        ("triangles", lambda: ratbez.Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1)])),
        ("vertices", lambda: ratbez.Mesh([(0, 0, NAN)], [])),
    ],
)
def test_functions_reject(argument, call):
    raises_naming(argument, call)


def test_invalid_solids_are_refused():
    # An open profile whose ends are off the axis cannot bound a solid.
    with pytest.raises(ratbez.Error):
        ratbez.revolve(ratbez.line_segment((1, 0), (2, 1)), axis_dir=(0, 1, 0))
    # Pieces that do not join end to end.
    raises_naming("profile", ratbez.revolve, [ratbez.line_segment((1, 0), (2, 0)), ratbez.line_segment((3, 0), (1, 0))])
    # A profile crossing the axis.
    with pytest.raises(ratbez.Error):
        ratbez.revolve(ratbez.circle(1.0, normal=(0, 0, 1)), axis_dir=(0, 1, 0))
    # A bow tie: its sides cross at (1.5, 0.5); the message names the pieces and where.
    corners = [(1, 0), (2, 1), (2, 0), (1, 1)]
    bow_tie = [ratbez.line_segment(corners[i], corners[(i + 1) % 4]) for i in range(4)]
    error = raises_naming("profile", ratbez.revolve, bow_tie, axis_dir=(0, 1, 0))
    assert "pieces 0 and 2 cross or touch near (1.5, 0.5, 0)" in str(error), str(error)
    raises_naming("profile", ratbez.extrude, bow_tie, (0, 0, 1), 1.0)


def test_parameters_outside_the_domain():
    c = ratbez.BezierCurve(P3)
    for bad in (-0.1, 1.5, NAN):
        with pytest.raises(ratbez.Error):
            c.point(bad)
    with pytest.raises(ratbez.Error):
        ratbez.BezierSurface(NET).point(0.5, 2.0)
    with pytest.raises(ratbez.Error):
        ratbez.NurbsCurve(1, [0, 0, 1, 2, 2], P3).point(3.0)


@pytest.mark.parametrize(
    "argument, reason, call",
    [
        ("radius", "must be greater than 0", lambda: ratbez.sphere(-1)),
        ("minor_radius", "must be less than major_radius (else the tube meets the axis)", lambda: ratbez.torus(1, 2)),
        ("points[1]", "expected a point of 2 or 3 numbers, got 1", lambda: ratbez.BezierCurve([(0, 0), (1,)])),
        ("axis", "must be a non-zero vector", lambda: ratbez.cylinder(1, 1, axis=(0, 0, 0))),
        ("profile", "must be closed to bound the caps of an extrusion",
         lambda: ratbez.extrude(ratbez.line_segment((0, 0), (1, 0)), (0, 0, 1), 1.0)),
    ],
)
def test_error_carries_argument_and_reason(argument, reason, call):
    with pytest.raises(ratbez.Error) as info:
        call()
    error = info.value
    assert error.argument == argument
    assert error.reason == reason
    assert isinstance(error.argument, str) and isinstance(error.reason, str)
    assert str(error) == argument + ": " + reason  # the message is unchanged: the two fields joined


def test_error_reason_may_contain_the_separator():
    # A nested reason keeps its own "x: y"; the argument is what the kernel named, not a split of the text.
    corners = [(1, 0), (2, 1), (2, 0), (1, 1)]
    bow_tie = [ratbez.line_segment(corners[i], corners[(i + 1) % 4]) for i in range(4)]
    with pytest.raises(ratbez.Error) as info:
        ratbez.revolve(bow_tie, axis_dir=(0, 1, 0))
    assert info.value.argument == "profile"
    assert str(info.value) == "profile: " + info.value.reason


def test_error_raised_from_python_has_no_fields():
    error = ratbez.Error("made by hand")
    assert isinstance(error, ValueError) and str(error) == "made by hand"
    assert error.argument is None and error.reason is None
    assert "argument" in ratbez.Error.__doc__


# --- wrong-typed arguments: ratbez.Error naming the argument, for every bound function ----------------

SQUARE_PATCH = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 0)]]


@pytest.mark.parametrize("call, argument", [
    (lambda: ratbez.sphere("2"), "radius"),
    (lambda: ratbez.cylinder(1.0, height=None), "height"),
    (lambda: ratbez.torus(3.0, [1.0]), "minor_radius"),
    (lambda: ratbez.sphere(1.0).tessellate("fine"), "tolerance"),
    (lambda: ratbez.sphere(1.0).tessellate(1e-3, angle_deg="x"), "angle_deg"),
    (lambda: ratbez.revolve(ratbez.line_segment((1, 0, 0), (1, 0, 1)), angle="x"), "angle"),
    (lambda: ratbez.BezierSurface(SQUARE_PATCH).point("a", 0.0), "u"),
    (lambda: ratbez.BezierSurface(SQUARE_PATCH).derivative(0.5, 0.5, du=1.5), "du"),
    (lambda: ratbez.Solid.volume(3), "self"),
    (lambda: ratbez.default_tolerance(ratbez.circle(1.0)), "solid"),
])
def test_wrong_type_names_the_argument(call, argument):
    with pytest.raises(ratbez.Error) as info:
        call()
    assert info.value.argument == argument
    assert info.value.reason.startswith("expected ")


def test_wrong_call_shape_stays_a_type_error():
    # A missing or unknown argument is a wrong call, not a wrong value: Python's TypeError, as usual.
    with pytest.raises(TypeError):
        ratbez.sphere()
    with pytest.raises(TypeError):
        ratbez.sphere(1.0, bogus=2)


def test_type_error_raised_inside_a_call_is_kept():
    def progress(fraction):
        raise TypeError("from the callback")

    with pytest.raises(TypeError, match="from the callback"):
        ratbez.sphere(1.0).tessellate(1e-3, progress=progress)
