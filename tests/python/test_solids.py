"""Primitives, sweeps, the B-rep and tessellation through Python."""
import math

import numpy as np
import pytest

import ratbez
from conftest import close

VOLUME_TOL = 1e-8  # exact surfaces, Gauss quadrature: far tighter than any mesh


def square_profile_2d():
    """The closed square (1,0)-(2,0)-(2,1)-(1,1) in the xy plane, as degree-1 Bézier pieces (2D points)."""
    corners = [(1, 0), (2, 0), (2, 1), (1, 1)]
    return [ratbez.BezierCurve([corners[k], corners[(k + 1) % 4]]) for k in range(4)]


def test_circle_and_arc():
    c = ratbez.circle(2.0)
    assert isinstance(c, ratbez.NurbsCurve) and c.degree == 2 and c.is_rational
    assert c.domain == (0.0, 1.0)
    for k in range(17):
        assert close(math.hypot(*c.point(k / 16)), 2.0)
    tilted = ratbez.circle(1.0, center=(1, 2, 3), normal=(1, 0, 0))
    for k in range(9):
        x, y, z = tilted.point(k / 8)
        assert close(x, 1.0) and close(math.hypot(y - 2, z - 3), 1.0)
    a = ratbez.arc(1.0, 0.0, 90.0)
    assert close(a.point(0.0), (1, 0, 0)) and close(a.point(1.0), (0, 1, 0))
    a2 = ratbez.arc(radius=3, start_deg=90, end_deg=180, center=(1, 1), normal=(0, 0, 1))
    assert close(a2.point(1.0), (-2, 1, 0))
    segment = ratbez.line_segment((0, 0), (1, 2, 3))
    assert close(segment.point(segment.domain[1]), (1, 2, 3))


@pytest.mark.parametrize(
    "solid, volume, area",
    [
        (lambda: ratbez.sphere(2.0), 4 / 3 * math.pi * 8, 4 * math.pi * 4),
        (lambda: ratbez.sphere(radius=1.0, center=(1, 2)), 4 / 3 * math.pi, 4 * math.pi),
        (lambda: ratbez.cylinder(1.0, 2.0), 2 * math.pi, 2 * math.pi * 2 + 2 * math.pi),
        (lambda: ratbez.cylinder(radius=1, height=2, center=(1, 1, 1), axis=(1, 1, 0)), 2 * math.pi, 6 * math.pi),
        (lambda: ratbez.cone(1.0, 0.0, 3.0), math.pi, math.pi + math.pi * math.sqrt(10)),
        (lambda: ratbez.cone(radius1=2, radius2=1, height=1, center=(0, 0, 0), axis=(0, 1, 0)),
         math.pi / 3 * (4 + 2 + 1), math.pi * 5 + math.pi * 3 * math.sqrt(2)),
        (lambda: ratbez.torus(3.0, 1.0), 2 * math.pi ** 2 * 3, 4 * math.pi ** 2 * 3),
        (lambda: ratbez.torus(major_radius=3, minor_radius=1, center=(0, 0, 5), axis=(0, 0, 2)),
         6 * math.pi ** 2, 12 * math.pi ** 2),
    ],
)
def test_primitive_volume_and_area(solid, volume, area):
    s = solid()
    assert isinstance(s, ratbez.Solid)
    assert s.volume() == pytest.approx(volume, rel=VOLUME_TOL)
    assert s.area() == pytest.approx(area, rel=VOLUME_TOL)


def test_revolve_profiles():
    # A closed 2D profile about the y axis: a ring of square section, V = pi (2^2 - 1^2) * 1.
    ring = ratbez.revolve(square_profile_2d(), axis_point=(0, 0), axis_dir=(0, 1), angle=360.0)
    assert ring.volume() == pytest.approx(3 * math.pi, rel=VOLUME_TOL)
    # A partial revolution gets two planar end faces.
    quarter = ratbez.revolve(square_profile_2d(), (0, 0, 0), (0, 1, 0), 90)
    assert quarter.volume() == pytest.approx(3 * math.pi / 4, rel=VOLUME_TOL)
    assert sum(f.kind == "planar" for f in quarter.faces) == 2
    # An open profile whose ends lie on the axis: a NurbsCurve half circle gives the ball.
    ball = ratbez.revolve(ratbez.arc(1, -90, 90), axis_dir=(0, 1, 0))
    assert ball.volume() == pytest.approx(4 / 3 * math.pi, rel=VOLUME_TOL)
    # A single rational BezierCurve profile (Ex1.13 arc closed by two lines) mixed with NURBS pieces.
    arc = ratbez.BezierCurve([(0, 1), (1, 1), (1, 0)], weights=[2, 1, 1])  # quarter circle (1,0)->(0,1) reversed
    cap = ratbez.revolve([arc, ratbez.line_segment((1, 0), (0, 0))], axis_dir=(0, 1, 0))
    assert cap.volume() == pytest.approx(2 / 3 * math.pi, rel=VOLUME_TOL)


def test_extrude():
    square = [ratbez.line_segment(a, b) for a, b in
              [((0, 0), (1, 0)), ((1, 0), (1, 1)), ((1, 1), (0, 1)), ((0, 1), (0, 0))]]
    box = ratbez.extrude(square, direction=(0, 0, 1), distance=2.0)
    assert box.volume() == pytest.approx(2.0, rel=VOLUME_TOL)
    assert box.area() == pytest.approx(10.0, rel=VOLUME_TOL)
    rod = ratbez.extrude(ratbez.circle(1.0), (0, 0, 1), 3.0)
    assert rod.volume() == pytest.approx(3 * math.pi, rel=VOLUME_TOL)


def test_faces_and_loops():
    cyl = ratbez.cylinder(1.0, 2.0)
    faces = cyl.faces
    assert isinstance(faces, list) and len(faces) == 3 and all(isinstance(f, ratbez.Face) for f in faces)
    lateral = [f for f in faces if f.kind == "surface"]
    caps = [f for f in faces if f.kind == "planar"]
    assert len(lateral) == 1 and len(caps) == 2
    side = lateral[0]
    assert side.loops == []
    surface = side.surface
    assert isinstance(surface, ratbez.NurbsSurface)
    (u0, u1), (v0, v1) = surface.domain
    u, v = (u0 + u1) / 2, (v0 + v1) / 2
    p, n = side.point(u, v), side.normal(u, v)
    assert close(p, surface.point(u, v))
    assert close(math.hypot(p[0], p[1]), 1.0)
    assert n[0] * p[0] + n[1] * p[1] > 0.99  # outward
    for cap in caps:
        loops = cap.loops
        assert len(loops) == 1 and loops[0] and all(isinstance(c, ratbez.NurbsCurve) for c in loops[0])
        (a0, a1), (b0, b1) = cap.surface.domain
        normal = cap.normal((a0 + a1) / 2, (b0 + b1) / 2)
        centre_z = cap.point((a0 + a1) / 2, (b0 + b1) / 2)[2]
        assert close(abs(normal[2]), 1.0) and (normal[2] > 0) == (centre_z > 1.0)
    assert len(ratbez.sphere(1).faces) == 1 and len(ratbez.torus(2, 1).faces) == 1


def test_tessellate_returns_numpy_mesh():
    tolerance = 1e-2
    mesh = ratbez.sphere(1.0).tessellate(tolerance)
    assert isinstance(mesh, ratbez.Mesh)
    v, t = mesh.vertices, mesh.triangles
    assert isinstance(v, np.ndarray) and v.dtype == np.float64 and v.ndim == 2 and v.shape[1] == 3
    assert isinstance(t, np.ndarray) and t.dtype.kind in "iu" and t.ndim == 2 and t.shape[1] == 3
    assert len(v) > 10 and len(t) > 10
    assert t.min() >= 0 and t.max() < len(v)
    # The mesh straddles the sphere: its vertices within the tolerance outside it, the poles among them.
    radii = np.linalg.norm(v, axis=1)
    assert np.all(radii >= 1.0 - 1e-12) and np.all(radii <= 1.0 + tolerance)
    assert radii.max() > 1.0 + 0.5 * tolerance
    assert mesh.is_closed()
    exact = 4 / 3 * math.pi
    assert abs(exact - mesh.volume()) <= tolerance * 4 * math.pi
    assert mesh.area() == pytest.approx(4 * math.pi, rel=3e-2)
    # No zero-area triangles at the poles.
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    assert np.linalg.norm(np.cross(b - a, c - a), axis=1).min() > 0
    coarse = ratbez.cylinder(1, 1).tessellate(tolerance=0.1, angle_deg=30.0)
    assert coarse.is_closed() and coarse.volume() > 0


def test_mesh_from_tables():
    vertices = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    triangles = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    mesh = ratbez.Mesh(vertices, triangles)
    assert mesh.is_closed()
    assert mesh.volume() == pytest.approx(1 / 6)
    assert not ratbez.Mesh(vertices, triangles[:3]).is_closed()
    assert np.array_equal(mesh.triangles, np.array(triangles))


def test_extrude_with_holes():
    # A 10 x 6 rectangle with a circular hole and a square hole drawn clockwise: volume (A - holes) d.
    corners = [(0, 0), (10, 0), (10, 6), (0, 6)]
    outer = [ratbez.line_segment(corners[k], corners[(k + 1) % 4]) for k in range(4)]
    square = [(6, 2), (6, 4), (8, 4), (8, 2)]
    hole_square = [ratbez.line_segment(square[k], square[(k + 1) % 4]) for k in range(4)]
    solid = ratbez.extrude(outer, (0, 0, 1), 2.0, holes=[ratbez.circle(1.5, (3, 3, 0)), hole_square])
    assert solid.volume() == pytest.approx((60 - math.pi * 2.25 - 4) * 2, rel=1e-12)
    assert solid.euler_characteristic() == -2
    assert len(solid.faces) == 4 + 1 + 4 + 2  # a circle is one piece
    assert solid.tessellate(0.01).is_closed()
    with pytest.raises(ratbez.Error, match=r"^holes\[0\]: must lie inside the profile"):
        ratbez.extrude(outer, (0, 0, 1), 2.0, holes=[ratbez.circle(1, (20, 3, 0))])
    with pytest.raises(ratbez.Error, match=r"^holes: expected a list"):
        ratbez.extrude(outer, (0, 0, 1), 2.0, holes=ratbez.circle(1, (3, 3, 0)))
    with pytest.raises(ratbez.Error, match=r"^holes\[1\]: expected a BezierCurve"):
        ratbez.extrude(outer, (0, 0, 1), 2.0, holes=[ratbez.circle(1, (3, 3, 0)), 5])


@pytest.mark.parametrize(
    "make, kind, parameters",
    [
        (lambda: ratbez.sphere(2.0, center=(1, 2)), "sphere", {"radius": 2.0, "center": (1.0, 2.0, 0.0)}),
        (lambda: ratbez.cylinder(1.0, 2.0, center=(1, 1, 1), axis=(0, 0, 3)), "cylinder",
         {"radius": 1.0, "height": 2.0, "center": (1.0, 1.0, 1.0), "axis": (0.0, 0.0, 1.0)}),
        (lambda: ratbez.cone(2, 0, 1, axis=(0, 2, 0)), "cone",
         {"radius1": 2.0, "radius2": 0.0, "height": 1.0, "center": (0.0, 0.0, 0.0), "axis": (0.0, 1.0, 0.0)}),
        (lambda: ratbez.torus(3, 1, center=(0, 0, 5)), "torus",
         {"major_radius": 3.0, "minor_radius": 1.0, "center": (0.0, 0.0, 5.0), "axis": (0.0, 0.0, 1.0)}),
    ],
)
def test_primitives_remember_what_they_were_built_as(make, kind, parameters):
    s = make()
    assert s.kind == kind
    assert s.parameters == parameters
    # The parameters are the building function's keywords: they build the same solid again.
    again = getattr(ratbez, kind)(**s.parameters)
    assert again.parameters == s.parameters and again.volume() == s.volume()
    # The closed forms against the cubature of the exact faces.
    assert isinstance(s.exact_volume, float) and isinstance(s.exact_area, float)
    assert s.exact_volume == pytest.approx(s.volume(), rel=1e-12)
    assert s.exact_area == pytest.approx(s.area(), rel=1e-12)


def test_sweeps_remember_their_parameters_without_closed_forms():
    turned = ratbez.revolve(square_profile_2d(), axis_dir=(0, 2, 0), angle=90)
    assert turned.kind == "revolution"
    assert turned.parameters == {"axis_point": (0.0, 0.0, 0.0), "axis_dir": (0.0, 1.0, 0.0), "angle": 90.0}
    assert turned.exact_volume is None and turned.exact_area is None
    again = ratbez.revolve(square_profile_2d(), **turned.parameters)
    assert again.volume() == turned.volume()

    prism = ratbez.extrude(square_profile_2d(), (0, 0, 2), 3.0)
    assert prism.kind == "extrusion"
    assert prism.parameters == {"direction": (0.0, 0.0, 1.0), "distance": 3.0}
    assert prism.exact_volume is None and prism.exact_area is None
    for name in ("kind", "parameters", "exact_volume", "exact_area"):
        assert getattr(ratbez.Solid, name).__doc__, name
