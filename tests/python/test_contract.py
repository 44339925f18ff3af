"""Every name and keyword of the public Python contract (DESIGN.md) exists and returns plain Python types."""
import inspect
import re

import ratbez

CONTRACT_NAMES = """bernstein bspline_basis BezierCurve BezierSurface NurbsCurve NurbsSurface circle arc cylinder
cone sphere torus revolve extrude export_openscad write_step write_brep write_stl occt_check Error""".split()


def keywords(function):
    """The keyword names of a pybind11 function, read from its signature line."""
    first_line = function.__doc__.splitlines()[0]
    inside = first_line[first_line.index("(") + 1: first_line.rindex(")")]
    # "name: type = default"; defaults are numbers, tuples or None, never containing a colon.
    return [name for name in re.findall(r"(\w+):", inside) if name != "self"]


def test_contract_names_exist():
    core_names = [n for n in CONTRACT_NAMES if n not in
                  ("export_openscad", "write_stl", "write_step", "write_brep", "occt_check")]
    assert [n for n in core_names if not hasattr(ratbez, n)] == []
    if ratbez.has_cgal:
        assert hasattr(ratbez, "export_openscad") and hasattr(ratbez, "write_stl")
    if ratbez.has_occt:
        for name in ("write_step", "write_brep", "occt_check", "brep_string", "read_step", "read_brep"):
            assert hasattr(ratbez, name), name


def test_keyword_names():
    expected = [
        (ratbez.bernstein, ["i", "n", "u"]),
        (ratbez.bspline_basis, ["i", "p", "knots", "u"]),
        (ratbez.circle, ["radius", "center", "normal"]),
        (ratbez.arc, ["radius", "start_deg", "end_deg", "center", "normal"]),
        (ratbez.cylinder, ["radius", "height", "center", "axis"]),
        (ratbez.cone, ["radius1", "radius2", "height", "center", "axis"]),
        (ratbez.sphere, ["radius", "center"]),
        (ratbez.torus, ["major_radius", "minor_radius", "center", "axis"]),
        (ratbez.revolve, ["profile", "axis_point", "axis_dir", "angle"]),
        (ratbez.extrude, ["profile", "direction", "distance", "holes"]),  # holes: an addition, optional
        (ratbez.BezierCurve.point, ["u"]),
        (ratbez.BezierCurve.derivative, ["u", "order"]),
        (ratbez.BezierCurve.split, ["u"]),
        (ratbez.BezierSurface.point, ["u", "v"]),
        (ratbez.BezierSurface.derivative, ["u", "v", "du", "dv"]),
        (ratbez.BezierSurface.normal, ["u", "v"]),
        (ratbez.BezierSurface.isocurve_u, ["u0"]),
        (ratbez.BezierSurface.isocurve_v, ["v0"]),
        (ratbez.NurbsCurve.derivative, ["u", "order"]),
        (ratbez.NurbsSurface.derivative, ["u", "v", "du", "dv"]),
        (ratbez.Solid.tessellate, ["tolerance", "angle_deg", "max_triangles", "progress"]),
        (ratbez.Face.tessellate, ["tolerance", "angle_deg", "max_triangles", "progress"]),
        (ratbez.NurbsSurface.tessellate, ["tolerance", "angle_deg", "max_triangles", "progress"]),
        (ratbez.BezierSurface.tessellate, ["tolerance", "angle_deg", "max_triangles", "progress"]),
        (ratbez.Solid.volume, ["progress"]),
        (ratbez.Solid.area, ["progress"]),
    ]
    if ratbez.has_cgal:
        # module, binary, max_triangles, progress and write_off: the contract additions (DESIGN.md; long calls
        # take progress=callable)
        expected.append((ratbez.export_openscad,
                         ["solid_or_mesh", "path", "tolerance", "module", "max_triangles", "import_stl", "progress", "color"]))
        expected.append((ratbez.write_stl, ["solid_or_mesh", "path", "tolerance", "binary", "max_triangles", "progress"]))
        expected.append((ratbez.write_off, ["solid_or_mesh", "path", "tolerance", "max_triangles", "progress"]))
        expected.append((ratbez.check_mesh, ["mesh", "check_self_intersections", "progress"]))
    if ratbez.has_occt:
        # bezier_faces, analytic_primitives: additions, optional (one face per Bézier patch, for FreeCAD's
        # measurements; OCCT's own primitives for the four kinds, issue 25)
        expected.append((ratbez.write_step, ["solid", "path", "bezier_faces", "analytic_primitives"]))
        expected.append((ratbez.write_brep, ["solid", "path", "bezier_faces", "analytic_primitives"]))
        expected.append((ratbez.read_step, ["path", "progress"]))
        expected.append((ratbez.read_brep, ["path", "progress"]))
        expected.append((ratbez.occt_check, ["solid", "grid", "deviation_limit", "volume_limit", "bezier_faces",
                                             "analytic_primitives", "progress"]))
    for function, names in expected:
        assert keywords(function) == names, function.__name__
    # Constructors: __init__(self, ...).
    assert keywords(ratbez.BezierCurve.__init__) == ["points", "weights"]
    assert keywords(ratbez.BezierSurface.__init__) == ["net", "weights"]
    assert keywords(ratbez.NurbsCurve.__init__) == ["degree", "knots", "points", "weights"]
    assert keywords(ratbez.NurbsSurface.__init__) == ["degree_u", "degree_v", "knots_u", "knots_v", "net", "weights"]


def test_calls_with_keywords_and_plain_return_types():
    c = ratbez.BezierCurve(points=[(0, 0), (1, 1)], weights=None)
    p = c.point(u=0.5)
    assert type(p) is tuple and len(p) == 3 and all(type(x) is float for x in p)
    assert type(c.points) is list and type(c.weights) is list and type(c.degree) is int
    assert type(c.is_rational) is bool
    halves = c.split(u=0.5)
    assert type(halves) is tuple and len(halves) == 2
    s = ratbez.BezierSurface(net=[[(0, 0), (0, 1)], [(1, 0), (1, 1)]])
    assert type(s.point(u=0.2, v=0.3)) is tuple
    assert type(s.derivative(u=0.2, v=0.3, du=0, dv=1)) is tuple
    assert type(s.normal(u=0.2, v=0.3)) is tuple and s.normal(0.2, 0.3) == (0.0, 0.0, 1.0)
    n = ratbez.NurbsCurve(degree=1, knots=[0, 0, 1, 1], points=[(0, 0), (1, 1)], weights=None)
    assert type(n.domain) is tuple and type(n.knots) is list
    ns = ratbez.NurbsSurface(degree_u=1, degree_v=1, knots_u=[0, 0, 1, 1], knots_v=[0, 0, 1, 1],
                             net=[[(0, 0), (0, 1)], [(1, 0), (1, 1)]], weights=None)
    assert ns.domain == ((0.0, 1.0), (0.0, 1.0)) and type(ns.points[0][0]) is tuple
    solid = ratbez.sphere(radius=1.0, center=(0, 0, 0))
    assert type(solid.faces) is list and type(solid.volume()) is float and type(solid.area()) is float
    assert type(ratbez.bernstein(i=0, n=1, u=0.5)) is float
    assert inspect.isclass(ratbez.Solid) and inspect.isclass(ratbez.Mesh) and inspect.isclass(ratbez.Face)
