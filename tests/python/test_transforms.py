"""Affine transforms of curves, surfaces, faces and solids: exact for rational geometry (the image of
every point is the map of the point: affine invariance, P1.14 / Exercise 1.4), weights and knots kept,
faces kept outward under mirrors, a Solid's kind and closed forms kept where the map preserves them, and
bad maps refused naming the argument."""
import math

import numpy as np
import pytest

import ratbez
from conftest import needs_occt, raises_naming

RNG = np.random.default_rng(4242)

# A general affine map (shear, non-uniform scale, translation) with det > 0, and a reflecting one.
SHEAR = np.array([[1.5, 0.4, -0.2, 1.0], [0.1, 0.8, 0.3, -2.0], [-0.3, 0.2, 1.2, 0.5]])
REFLECT = np.array([[-1.0, 0.2, 0.0, 0.3], [0.0, 1.1, 0.1, 0.0], [0.2, 0.0, 0.9, -1.0]])


def apply(matrix, points):
    points = np.asarray(points, dtype=float)
    return points @ matrix[:, :3].T + matrix[:, 3]


def same_points(a, b, scale=10.0):
    assert np.max(np.abs(np.asarray(a) - np.asarray(b))) <= 1e-14 * scale


def curves():
    yield ratbez.BezierCurve(RNG.uniform(-2, 2, (4, 3)).tolist(), RNG.uniform(0.3, 3, 4).tolist())
    yield ratbez.NurbsCurve(2, [0, 0, 0, 0.3, 0.7, 1, 1, 1], RNG.uniform(-2, 2, (5, 3)).tolist(),
                            RNG.uniform(0.3, 3, 5).tolist())
    yield ratbez.circle(2, center=(1, 2, 3), normal=(1, 1, 1))


def surfaces():
    yield ratbez.BezierSurface(RNG.uniform(-2, 2, (3, 4, 3)).tolist(), RNG.uniform(0.3, 3, (3, 4)).tolist())
    yield ratbez.torus(2, 0.5).faces[0].surface


@pytest.mark.parametrize("matrix", [SHEAR, REFLECT], ids=["shear", "reflect"])
def test_curves_and_surfaces_map_exactly_with_weights_and_knots_kept(matrix):
    for curve in curves():
        image = curve.transformed(matrix)
        assert type(image) is type(curve) and image.weights == curve.weights
        assert getattr(image, "knots", None) == getattr(curve, "knots", None)
        us = np.linspace(*getattr(curve, "domain", (0, 1)), 17)
        same_points(image.evaluate(us), apply(matrix, curve.evaluate(us)))
        same_points(image.points, apply(matrix, curve.points))
    for surface in surfaces():
        image = surface.transformed(np.vstack([matrix, [0, 0, 0, 1]]))  # the 4 x 4 form
        assert type(image) is type(surface) and image.weights == surface.weights
        (u0, u1), (v0, v1) = getattr(surface, "domain", ((0, 1), (0, 1)))
        us, vs = np.linspace(u0, u1, 9), np.linspace(v0, v1, 7)
        same_points(image.evaluate(us, vs), apply(matrix, surface.evaluate(us, vs)))


def test_the_named_maps():
    c = ratbez.circle(1.0)
    # A quarter turn is exact: the control points move onto each other's axes with no rounding.
    turned = c.rotated((0, 0, 0), (0, 0, 2), 90)
    assert turned.points == [(-y, x, z) for x, y, z in c.points] and turned.weights == c.weights
    same_points(c.translated((1, 2)).points, np.array(c.points) + (1, 2, 0))
    same_points(c.scaled(3, center=(1, 0, 0)).points, (np.array(c.points) - (1, 0, 0)) * 3 + (1, 0, 0))
    same_points(c.mirrored((0, 0, 1), (0, 0, 5)).points, np.array(c.points) * (1, 1, -1) + (0, 0, 2))
    rotated = c.rotated(axis_point=(1, 0, 0), axis_dir=(0, 1, 0), angle_deg=30)
    for u in np.linspace(0, 1, 9):
        x, y, z = c.point(u)
        a = math.radians(30)
        expected = (1 + (x - 1) * math.cos(a) + z * math.sin(a), y, -(x - 1) * math.sin(a) + z * math.cos(a))
        same_points(rotated.point(u), expected)


def outward(solid):
    """Every face's normal points away from the solid's centre of mass (convex solids)."""
    mesh = solid.tessellate(0.01)
    centre = mesh.vertices.mean(axis=0)
    for face in solid.faces:
        (u0, u1), (v0, v1) = face.surface.domain
        us, vs = np.linspace(u0, u1, 5)[1:-1], np.linspace(v0, v1, 5)[1:-1]
        points, normals = face.evaluate(us, vs), face.normals(us, vs)
        # (A planar face's patch reaches past its loops, but its points still lie on the outer side.)
        assert np.all(np.einsum("ijk,ijk->ij", normals, points - centre) > 0)
    return mesh


@pytest.mark.parametrize("make", [lambda: ratbez.cylinder(1, 2, center=(1, 0, 0), axis=(0, 1, 1)),
                                  lambda: ratbez.sphere(1.5, center=(0, 1, 0)),
                                  lambda: ratbez.cone(1, 0.4, 2),
                                  lambda: ratbez.extrude([ratbez.circle(1)], (0, 0, 1), 2, holes=[[ratbez.circle(0.3)]])],
                         ids=["cylinder", "sphere", "cone", "extrusion_with_hole"])
def test_mirrors_keep_solids_outward(make):
    solid = make()
    images = ((solid.mirrored((0, 0, 0), (1, 2, 3)), 1.0), (solid.scaled(-2), 8.0),
              (solid.transformed(REFLECT), abs(np.linalg.det(REFLECT[:, :3]))))
    for image, factor in images:
        if solid.kind != "extrusion":
            outward(image)
        mesh = image.tessellate(0.01)
        assert mesh.is_closed() and mesh.volume() > 0
        assert image.volume() == pytest.approx(solid.volume() * factor, rel=1e-12)
        assert image.area() > 0


def test_solid_kinds_follow_the_map():
    sphere = ratbez.sphere(2, center=(1, 2, 3))
    moved = sphere.rotated((0, 0, 0), (1, 1, 0), 33).translated((1, 0, 0)).scaled(1.5)
    assert moved.kind == "sphere" and moved.parameters["radius"] == pytest.approx(3.0, rel=1e-15)
    assert moved.exact_volume == pytest.approx(sphere.exact_volume * 1.5 ** 3, rel=1e-14)
    assert moved.volume() == pytest.approx(moved.exact_volume, rel=1e-12)
    centre = np.array(moved.parameters["center"])
    mesh = moved.tessellate(0.01)
    assert np.allclose(np.linalg.norm(mesh.vertices - centre, axis=1), 3.0, atol=0.011)

    torus = ratbez.torus(3, 1, axis=(0, 1, 0)).mirrored((0, 0, 0), (1, 1, 0))
    assert torus.kind == "torus" and torus.exact_area == pytest.approx(12 * math.pi ** 2, rel=1e-14)
    squashed = ratbez.torus(3, 1).transformed([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0.5, 0]])
    assert squashed.kind == "none" and squashed.parameters == {} and squashed.exact_volume is None
    assert squashed.volume() == pytest.approx(6 * math.pi ** 2 * 0.5, rel=1e-12)

    revolved = ratbez.revolve([ratbez.BezierCurve([(1, 0, 0), (2, 0, 1), (1, 0, 2)]),
                               ratbez.BezierCurve([(1, 0, 2), (1, 0, 0)])], angle=270)
    mirrored = revolved.mirrored((0, 0, 0), (1, 0, 0))
    assert mirrored.kind == "revolution" and mirrored.parameters["angle"] == 270
    assert mirrored.parameters["axis_dir"] == pytest.approx((0, 0, -1))  # the sweep's sense turns
    assert mirrored.volume() == pytest.approx(revolved.volume(), rel=1e-12)

    prism = ratbez.extrude([ratbez.circle(1)], (0, 0, 1), 2)
    sheared = prism.transformed(SHEAR)
    assert sheared.kind == "extrusion"
    direction = SHEAR[:, :3] @ (0, 0, 1)
    assert sheared.parameters["distance"] == pytest.approx(2 * np.linalg.norm(direction), rel=1e-14)
    assert sheared.parameters["direction"] == pytest.approx(direction / np.linalg.norm(direction), rel=1e-14)
    assert sheared.volume() == pytest.approx(prism.volume() * np.linalg.det(SHEAR[:, :3]), rel=1e-12)
    assert sphere.transformed(SHEAR).kind == "none"
    assert sphere.translated((0, 0, 0)) is not sphere and sphere.parameters["center"] == (1.0, 2.0, 3.0)


def test_faces_transform_alone():
    cylinder = ratbez.cylinder(1, 2)
    for face in cylinder.faces:
        image = face.mirrored((0, 0, 0), (0, 1, 0))
        assert image.kind == face.kind
        (u0, u1), (v0, v1) = face.surface.domain
        u, v = 0.3 * u0 + 0.7 * u1, 0.6 * v0 + 0.4 * v1
        # The mirror image of the outward normal is the image's outward normal (at the mirrored point).
        x, y, z = face.normal(u, v)
        normal = np.array([x, -y, z])
        (a0, a1), (b0, b1) = image.surface.domain
        grid = image.surface.evaluate(np.linspace(a0, a1, 41), np.linspace(b0, b1, 41)).reshape(-1, 3)
        normals = image.normals(np.linspace(a0, a1, 41), np.linspace(b0, b1, 41)).reshape(-1, 3)
        px, py, pz = face.point(u, v)
        nearest = np.argmin(np.linalg.norm(grid - (px, -py, pz), axis=1))
        assert np.dot(normals[nearest], normal) > 0.9


@needs_occt
def test_a_moved_primitive_still_matches_occts_analytic_surface():
    cone = ratbez.cone(2, 0.5, 3).rotated((1, 0, 0), (1, 2, 0), 40).mirrored((0, 0, 1), (0, 1, 1))
    report = ratbez.occt_check(cone)
    assert report["valid"] and cone.kind == "cone"
    assert report["max_analytic_deviation"] < 1e-9
    assert report["closed_form_volume"] == pytest.approx(cone.exact_volume, rel=1e-12)


def test_bad_maps_name_the_argument():
    c = ratbez.circle(1)
    raises_naming("matrix", c.transformed, [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0.1, 1]])  # projective
    raises_naming("matrix", c.transformed, [[1, 0, 0, 0], [0, 1, 0, 0], [1, 1, 0, 0]])  # singular
    raises_naming("matrix", c.transformed, np.eye(3))
    raises_naming("matrix", c.transformed, [[1, 0, 0, math.nan], [0, 1, 0, 0], [0, 0, 1, 0]])
    raises_naming("matrix", c.transformed, "identity")
    raises_naming("axis_dir", c.rotated, (0, 0, 0), (0, 0, 0), 10)
    raises_naming("angle_deg", c.rotated, (0, 0, 0), (0, 0, 1), math.inf)
    raises_naming("factor", c.scaled, 0)
    raises_naming("plane_normal", ratbez.sphere(1).mirrored, (0, 0, 0), (0, 0, 0))
    raises_naming("v", c.translated, (1, 2, 3, 4))


def test_a_solid_moved_too_far_for_its_size_names_the_map():
    # sphere(2) moved to 1e15 was refused naming "sides" ("side u_max collapses to a point"), at 1e10 "faces".
    for distance in (1e10, 1e15):
        with pytest.raises(ratbez.Error) as caught:
            ratbez.sphere(2).translated((distance, 0, 0))
        assert caught.value.argument == "v", str(caught.value)
        assert "from the origin, where neighbouring doubles are" in str(caught.value)
    raises_naming("factor", ratbez.sphere(1).scaled, 1e120)
    raises_naming("axis_point", ratbez.sphere(1, center=(1, 0, 0)).rotated, (1e15, 0, 0), (0, 0, 1), 180)
    raises_naming("matrix", ratbez.sphere(1).transformed, [[1, 0, 0, 1e15], [0, 1, 0, 0], [0, 0, 1, 0]])
    # Near enough it is still moved, exactly.
    assert ratbez.sphere(2).translated((1e8, 0, 0)).bounding_box()[0][0] == pytest.approx(1e8 - 2)
