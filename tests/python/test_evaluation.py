"""Bulk evaluation into numpy (curve.evaluate, surface.evaluate / evaluate_at / normals) against the
per-point calls it batches: random rational NURBS and Bezier curves and surfaces with interior knots of
every multiplicity, at random parameters, the domain's ends, the knots and the poles of a sphere; then
unsorted and repeated parameters, empty input and every kind of bad input.

Agreement is to 1e-14 relative: the largest coordinate difference over an array is at most 1e-14 of the
largest coordinate of the per-point values (relative to the array, since a partial that vanishes at a
pole is 0 in one evaluation order and 1e-17 in another)."""
import math

import numpy as np
import pytest

import ratbez
from conftest import raises_naming

RNG = np.random.default_rng(20261215)
RELATIVE = 1e-14


def agree(bulk, reference):
    reference = np.asarray(reference, dtype=float)
    assert bulk.shape == reference.shape and bulk.dtype == np.float64
    scale = max(np.max(np.abs(reference)), 1e-300)
    assert np.max(np.abs(bulk - reference)) <= RELATIVE * scale, np.max(np.abs(bulk - reference)) / scale


def random_knots(degree, count, clamped=True):
    """A valid knot vector for `degree` and `count` control points, interior multiplicities 1..degree."""
    interior = count - degree - 1
    values = []
    while len(values) < interior:
        value = float(RNG.uniform(0.05, 0.95))
        values += [value] * min(int(RNG.integers(1, max(degree, 1) + 1)), interior - len(values))
    start, width = float(RNG.uniform(-2, 2)), float(RNG.uniform(0.5, 3))
    return [start] * (degree + 1) + [start + width * v for v in sorted(values)] + [start + width] * (degree + 1)


def random_nurbs_surface(p, q, rational=True):
    rows, columns = p + int(RNG.integers(1, 5)), q + int(RNG.integers(1, 5))
    net = RNG.uniform(-3, 3, (rows, columns, 3)).tolist()
    weights = RNG.uniform(0.2, 5, (rows, columns)).tolist() if rational else None
    return ratbez.NurbsSurface(p, q, random_knots(p, rows), random_knots(q, columns), net, weights)


def random_nurbs_curve(p, rational=True):
    count = p + int(RNG.integers(1, 6))
    weights = RNG.uniform(0.2, 5, count).tolist() if rational else None
    return ratbez.NurbsCurve(p, random_knots(p, count), RNG.uniform(-3, 3, (count, 3)).tolist(), weights)


def parameters(domain, knots=(), count=9):
    """Random parameters with both ends and the knots inside the domain, shuffled."""
    a, b = domain
    ts = list(RNG.uniform(a, b, count)) + [a, b] + [k for k in knots if a <= k <= b]
    RNG.shuffle(ts)
    return np.array(ts)


def surfaces():
    yield "bezier rational", ratbez.BezierSurface(RNG.uniform(-2, 2, (4, 3, 3)).tolist(),
                                                  RNG.uniform(0.3, 3, (4, 3)).tolist())
    yield "bezier polynomial", ratbez.BezierSurface(RNG.uniform(-2, 2, (3, 5, 3)).tolist())
    for p, q in ((1, 1), (2, 3), (3, 2), (5, 4), (9, 2)):
        yield f"nurbs {p}x{q}", random_nurbs_surface(p, q)
    yield "nurbs polynomial", random_nurbs_surface(3, 3, rational=False)
    yield "sphere", ratbez.sphere(2.5, center=(1, -2, 0.5)).faces[0].surface
    yield "torus", ratbez.torus(2, 0.5).faces[0].surface


def surface_grid(surface):
    if isinstance(surface, ratbez.BezierSurface):
        return parameters((0, 1)), parameters((0, 1))
    (u0, u1), (v0, v1) = surface.domain
    return parameters((u0, u1), surface.knots_u), parameters((v0, v1), surface.knots_v, count=7)


@pytest.mark.parametrize("name,surface", list(surfaces()), ids=[n for n, _ in surfaces()])
def test_surface_evaluate_agrees_with_the_per_point_calls(name, surface):
    us, vs = surface_grid(surface)
    for du, dv in ((0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2), (3, 1)):
        grid = surface.evaluate(us, vs, du, dv)
        if (du, dv) == (0, 0):
            reference = [[surface.point(u, v) for v in vs] for u in us]
        else:
            reference = [[surface.derivative(u, v, du, dv) for v in vs] for u in us]
        agree(grid, reference)
        pairs = np.array([(u, v) for u in us for v in vs])
        agree(surface.evaluate_at(pairs, du=du, dv=dv), np.reshape(reference, (-1, 3)))
    normals = surface.normals(us, vs)
    agree(normals, [[surface.normal(u, v) for v in vs] for u in us])
    assert np.allclose(np.linalg.norm(normals, axis=2), 1, rtol=0, atol=1e-14)


def fixed_surfaces():
    """Surfaces drawn without the module's RNG (drawing here would shift the other tests' random cases)."""
    profile = ratbez.BezierCurve([(0, 0, 0), (1.6, 0, 0.2), (1.1, 0, 1.7), (0, 0, 2)], [1.0, 0.6, 1.8, 1.0])
    net = [[(i, j, (i * j) % 3 - 0.5 * i) for j in range(4)] for i in range(3)]
    weights = [[1.0, 0.5, 2.0, 1.0], [0.7, 1.3, 1.0, 0.9], [1.0, 1.0, 0.6, 1.0]]
    return {"sphere": ratbez.sphere(1.0).faces[0].surface, "torus face": ratbez.torus(2.0, 0.5).faces[0],
            "revolved cubic": ratbez.revolve(profile).faces[0].surface,
            "bezier": ratbez.BezierSurface(net, weights)}


@pytest.mark.parametrize("name", list(fixed_surfaces()))
def test_evaluate_partials_is_every_partial_in_one_array(name):
    surface = fixed_surfaces()[name]
    if isinstance(surface, ratbez.BezierSurface):
        us, vs = np.linspace(1, 0, 11), np.linspace(0, 1, 7)
    else:
        (u0, u1), (v0, v1) = (surface.surface if isinstance(surface, ratbez.Face) else surface).domain
        us, vs = np.linspace(u1, u0, 11), np.linspace(v0, v1, 7)  # any order
    for order, partials in ((1, ((0, 0), (1, 0), (0, 1))), (2, ((0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)))):
        table = surface.evaluate_partials(us, vs, order=order)
        assert table.shape == (len(us), len(vs), len(partials), 3)
        for k, (du, dv) in enumerate(partials):
            agree(table[:, :, k, :], surface.evaluate(us, vs, du, dv))
    raises_naming("order", surface.evaluate_partials, us, vs, order=3)


def test_sphere_normals_at_the_poles_are_the_limit_normals():
    sphere = ratbez.sphere(2.0, center=(1, 1, 1))
    surface = sphere.faces[0].surface
    (u0, u1), (v0, v1) = surface.domain
    us, vs = np.linspace(u0, u1, 5), np.array([v0, v1])
    normals = surface.normals(us, vs)
    points = surface.evaluate(us, vs)
    # At the poles S_u x S_v vanishes; the limit normal is the radial direction (0, 0, -+1).
    assert np.allclose((points - (1, 1, 1)) / 2, normals, rtol=0, atol=1e-14)
    assert {round(z) for z in normals[:, :, 2].ravel()} == {-1, 1}


@pytest.mark.parametrize("order", [0, 1, 2, 3])
def test_curve_evaluate_agrees_with_the_per_point_calls(order):
    curves = [random_nurbs_curve(p) for p in (1, 2, 3, 5)] + [random_nurbs_curve(3, rational=False)]
    curves += [ratbez.BezierCurve(RNG.uniform(-2, 2, (5, 3)).tolist(), RNG.uniform(0.3, 3, 5).tolist()),
               ratbez.BezierCurve([(0, 0), (1, 2), (3, 1)]), ratbez.circle(3, center=(1, 2, 3), normal=(1, 1, 0))]
    for curve in curves:
        domain = (0, 1) if isinstance(curve, ratbez.BezierCurve) else curve.domain
        us = parameters(domain, getattr(curve, "knots", ()), count=15)
        values = curve.evaluate(us, order)
        reference = [curve.point(u) if order == 0 else curve.derivative(u, order) for u in us]
        agree(values, reference)


def test_face_methods_go_through_its_surface():
    solid = ratbez.cylinder(1.5, 2.0, center=(0, 0, 1))
    for face in solid.faces:
        (u0, u1), (v0, v1) = face.surface.domain
        us, vs = np.linspace(u0, u1, 4), np.linspace(v0, v1, 3)
        assert np.array_equal(face.evaluate(us, vs), face.surface.evaluate(us, vs))
        agree(face.normals(us, vs), [[face.normal(u, v) for v in vs] for u in us])
        assert np.array_equal(face.evaluate_at([(u0, v0), (u1, v1)]), face.surface.evaluate_at([(u0, v0), (u1, v1)]))


def test_unsorted_repeated_and_empty_parameters_keep_their_places():
    surface = random_nurbs_surface(3, 3)
    (u0, u1), (v0, v1) = surface.domain
    us = np.array([u1, u0, 0.5 * (u0 + u1), u0, u1])
    vs = np.array([0.3 * v0 + 0.7 * v1, v0, v0, v1])
    grid = surface.evaluate(us, vs, du=1)
    for i, u in enumerate(us):
        for j, v in enumerate(vs):
            assert np.allclose(grid[i, j], surface.derivative(u, v, 1, 0), rtol=1e-14, atol=1e-14)
    assert surface.evaluate([], vs).shape == (0, 4, 3)
    assert surface.evaluate(us, []).shape == (5, 0, 3)
    assert surface.evaluate_at(np.empty((0, 2))).shape == (0, 3)
    assert ratbez.circle(1).evaluate([]).shape == (0, 3)


def test_array_likes_of_any_real_dtype_are_accepted():
    curve = ratbez.BezierCurve([(0, 0), (1, 1), (2, 0)])
    expected = curve.evaluate(np.array([0.0, 0.5, 1.0]))
    for us in ([0, 0.5, 1], (0, 0.5, 1), np.array([0, 0.5, 1], dtype=np.float32)):
        assert np.array_equal(curve.evaluate(us), expected)
    assert np.array_equal(curve.evaluate(np.array([0, 1], dtype=np.int64)), expected[[0, 2]])
    assert np.array_equal(curve.evaluate(np.array([0.0, 0.5, 1.0, 0.25])[::2]), expected[[0, 2]])  # strided


def test_bad_input_names_the_argument():
    surface = random_nurbs_surface(2, 2)
    (u0, u1), (v0, v1) = surface.domain
    good = np.array([u0, u1])
    error = raises_naming("us", surface.evaluate, [u0, u1 + 1], [v0])
    assert error.argument == "us" and "element 1" in error.reason and "outside the domain" in error.reason
    raises_naming("vs", surface.evaluate, good, [v0, math.nan])
    raises_naming("vs", surface.normals, good, [math.inf])
    raises_naming("us", surface.evaluate, [[u0]], [v0])          # 2-D where 1-D belongs
    raises_naming("us", surface.evaluate, u0, [v0])              # a scalar
    raises_naming("us", surface.evaluate, ["a"], [v0])           # strings
    raises_naming("us", surface.evaluate, [1j], [v0])            # complex
    raises_naming("us", surface.evaluate, [True], [v0])          # bool
    raises_naming("us", surface.evaluate, None, [v0])
    raises_naming("us", surface.evaluate, [[u0], [u0, u1]], [v0])  # ragged
    raises_naming("du", surface.evaluate, good, [v0], du=-1)
    raises_naming("uv", surface.evaluate_at, [(u0, v0, 0)])
    raises_naming("uv", surface.evaluate_at, [u0, v0])
    error = raises_naming("uv", surface.evaluate_at, [(u0, v0), (u0, v1 + 1)])
    assert "row 1" in error.reason and "v" in error.reason
    curve = ratbez.BezierCurve([(0, 0), (1, 1)])
    raises_naming("us", curve.evaluate, [0.5, -0.1])
    raises_naming("order", curve.evaluate, [0.5], order=-1)
    with pytest.raises(ValueError):  # ratbez.Error is a ValueError
        curve.evaluate([2.0])
