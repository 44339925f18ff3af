// Value semantics: pickle, copy and deepcopy for every class, == and hash by value for curves and surfaces.
//
// Every object pickles to ratbez._restore(type name, state), where the state is its exact data as plain
// tuples of numbers: degrees, knots and homogeneous control points (w x, w y, w z, w) for curves and
// surfaces, the indexed B-rep tables (brep_tables.hpp) and the construction record for a Face or Solid,
// the vertex and triangle tables for a Mesh. Restoring goes through the validating constructors, so a
// corrupted pickle is refused like any bad input; an intact one gives back the same numbers exactly.
// (A module function rather than __getstate__ / __setstate__: restoring then never needs a bare
// instance from __new__.)

#include <pybind11/eval.h>

#include <functional>
#include <string>
#include <vector>

#include "convert.hpp"
#include "numpy_arrays.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/brep_tables.hpp"
#include "ratbez/construction.hpp"
#include "ratbez/construction_check.hpp"
#include "ratbez/error.hpp"
#include "ratbez/mesh.hpp"

namespace ratbez::python {

namespace {

// ---- numbers ----------------------------------------------------------------------------------------

py::tuple number_tuple(const std::vector<double>& values) {
    py::tuple t(values.size());
    for (std::size_t k = 0; k < values.size(); ++k) t[k] = values[k];
    return t;
}

py::tuple homogeneous_tuple(const std::vector<Vec4>& points) {
    std::vector<double> flat;
    flat.reserve(4 * points.size());
    for (const Vec4& p : points) flat.insert(flat.end(), {p.x, p.y, p.z, p.w});
    return number_tuple(flat);
}

std::vector<Vec4> homogeneous_from(py::handle value, const std::string& argument) {
    const std::vector<double> flat = to_doubles(value, argument);
    if (flat.size() % 4 != 0) throw Error(argument, "expected (w x, w y, w z, w) quadruples");
    std::vector<Vec4> points(flat.size() / 4);
    for (std::size_t k = 0; k < points.size(); ++k)
        points[k] = {flat[4 * k], flat[4 * k + 1], flat[4 * k + 2], flat[4 * k + 3]};
    return points;
}

py::tuple vec_tuple(const Vec3& v) { return py::make_tuple(v.x, v.y, v.z); }

// The items of a state tuple, `count` of them (or, with `most` > count, count to most of them: a state that
// grew fields keeps reading the pickles written before).
std::vector<py::object> state_items(py::handle state, std::size_t count, const std::string& argument, std::size_t most = 0) {
    most = std::max(most, count);
    if (!py::isinstance<py::tuple>(state) || py::len(state) < count || py::len(state) > most)
        throw Error(argument, most == count ? "expected a tuple of " + std::to_string(count) + " items"
                                            : "expected a tuple of " + std::to_string(count) + " to " + std::to_string(most) + " items");
    std::vector<py::object> items;
    for (py::handle item : state) items.push_back(py::reinterpret_borrow<py::object>(item));
    return items;
}

bool to_bool(py::handle value, const std::string& argument) {
    if (!py::isinstance<py::bool_>(value)) throw Error(argument, "expected True or False");
    return value.cast<bool>();
}

std::size_t to_index(py::handle value, const std::string& argument) {
    const int index = to_int(value, argument);
    if (index < 0) throw Error(argument, "expected an index >= 0");
    return static_cast<std::size_t>(index);
}

// ---- curves and surfaces ----------------------------------------------------------------------------

py::tuple state_of(const BezierCurve& c) { return py::make_tuple(homogeneous_tuple(c.homogeneous_points()), c.is_rational()); }
py::tuple state_of(const NurbsCurve& c) {
    return py::make_tuple(c.degree(), number_tuple(c.knots()), homogeneous_tuple(c.homogeneous_points()), c.is_rational());
}
py::tuple state_of(const BezierSurface& s) {
    return py::make_tuple(s.degree_u() + 1, s.degree_v() + 1, homogeneous_tuple(s.homogeneous_points()), s.is_rational());
}
py::tuple state_of(const NurbsSurface& s) {
    return py::make_tuple(s.degree_u(), s.degree_v(), number_tuple(s.knots_u()), number_tuple(s.knots_v()),
                          homogeneous_tuple(s.homogeneous_points()), s.is_rational());
}

BezierCurve bezier_curve_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 2, at);
    return BezierCurve::from_homogeneous(homogeneous_from(items[0], at + ".points"), to_bool(items[1], at + ".rational"));
}
NurbsCurve nurbs_curve_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 4, at);
    return NurbsCurve::from_homogeneous(to_int(items[0], at + ".degree"), to_doubles(items[1], at + ".knots"),
                                        homogeneous_from(items[2], at + ".points"), to_bool(items[3], at + ".rational"));
}
BezierSurface bezier_surface_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 4, at);
    return BezierSurface::from_homogeneous(to_int(items[0], at + ".rows"), to_int(items[1], at + ".columns"),
                                           homogeneous_from(items[2], at + ".points"), to_bool(items[3], at + ".rational"));
}
NurbsSurface nurbs_surface_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 6, at);
    return NurbsSurface::from_homogeneous(to_int(items[0], at + ".degree_u"), to_int(items[1], at + ".degree_v"),
                                          to_doubles(items[2], at + ".knots_u"), to_doubles(items[3], at + ".knots_v"),
                                          homogeneous_from(items[4], at + ".points"), to_bool(items[5], at + ".rational"));
}

// ---- B-rep tables and construction records ------------------------------------------------------------

py::tuple coedge_state(const BrepTables::CoedgeRecord& c) {
    if (c.pcurve) return py::make_tuple(c.edge, c.reversed, state_of(*c.pcurve));
    return py::make_tuple(c.edge, c.reversed);
}

py::tuple loops_state(const std::vector<std::vector<BrepTables::CoedgeRecord>>& loops) {
    py::list out;
    for (const auto& loop : loops) {
        py::list coedges;
        for (const auto& c : loop) coedges.append(coedge_state(c));
        out.append(py::tuple(coedges));
    }
    return py::tuple(out);
}

py::tuple tables_state(const BrepTables& t) {
    py::list vertices, edges, faces;
    for (const Vec3& p : t.vertices) vertices.append(vec_tuple(p));
    for (const auto& e : t.edges) edges.append(py::make_tuple(state_of(e.curve), e.start, e.end, e.degenerate));
    for (const auto& f : t.faces) {
        if (f.kind == Face::Kind::surface) {
            py::list sides;
            for (const auto& c : f.sides) sides.append(coedge_state(c));
            faces.append(py::make_tuple("surface", state_of(*f.surface), py::tuple(sides)));
        } else if (f.kind == Face::Kind::trimmed) {
            faces.append(py::make_tuple("trimmed", state_of(*f.surface), loops_state(f.loops), f.tolerance));
        } else {
            const Plane& p = f.plane;
            faces.append(py::make_tuple(
                "planar", py::make_tuple(vec_tuple(p.origin), vec_tuple(p.x_axis), vec_tuple(p.y_axis), vec_tuple(p.normal)),
                loops_state(f.loops), f.tolerance));
        }
    }
    return py::make_tuple(py::tuple(vertices), py::tuple(edges), py::tuple(faces));
}

BrepTables::CoedgeRecord coedge_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 2, at, 3);
    BrepTables::CoedgeRecord c{to_index(items[0], at + ".edge"), to_bool(items[1], at + ".reversed"), std::nullopt};
    if (items.size() == 3) c.pcurve = nurbs_curve_from(items[2], at + ".pcurve");
    return c;
}

std::vector<std::vector<BrepTables::CoedgeRecord>> loops_from(py::handle state, const std::string& at) {
    std::vector<std::vector<BrepTables::CoedgeRecord>> loops;
    for (py::handle loop : state) {
        std::vector<BrepTables::CoedgeRecord> coedges;
        for (py::handle c : loop) coedges.push_back(coedge_from(c, at));
        loops.push_back(std::move(coedges));
    }
    return loops;
}

BrepTables tables_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 3, at);
    BrepTables t;
    t.vertices = to_points(items[0], at + ".vertices");
    std::size_t k = 0;
    for (py::handle e : items[1]) {
        const std::string where = at + ".edges[" + std::to_string(k++) + "]";
        const auto edge = state_items(e, 4, where);
        t.edges.push_back({nurbs_curve_from(edge[0], where + ".curve"), to_index(edge[1], where + ".start"),
                           to_index(edge[2], where + ".end"), to_bool(edge[3], where + ".degenerate")});
    }
    k = 0;
    for (py::handle f : items[2]) {
        const std::string where = at + ".faces[" + std::to_string(k++) + "]";
        const auto face = state_items(f, 3, where, 4);
        BrepTables::FaceRecord record;
        const std::string kind = py::isinstance<py::str>(face[0]) ? face[0].cast<std::string>() : "";
        const auto tolerance = [&] { return face.size() == 4 ? to_double(face[3], where + ".tolerance") : 0.0; };
        if (kind == "surface") {
            record.surface = nurbs_surface_from(face[1], where + ".surface");
            const auto sides = state_items(face[2], 4, where + ".sides");
            for (std::size_t s = 0; s < 4; ++s) record.sides[s] = coedge_from(sides[s], where + ".sides");
        } else if (kind == "planar") {
            record.kind = Face::Kind::planar;
            const auto plane = state_items(face[1], 4, where + ".plane");
            record.plane = {to_vec3(plane[0], where + ".plane"), to_vec3(plane[1], where + ".plane"),
                            to_vec3(plane[2], where + ".plane"), to_vec3(plane[3], where + ".plane")};
            record.loops = loops_from(face[2], where + ".loops");
            record.tolerance = tolerance();
        } else if (kind == "trimmed") {
            record.kind = Face::Kind::trimmed;
            record.surface = nurbs_surface_from(face[1], where + ".surface");
            record.loops = loops_from(face[2], where + ".loops");
            record.tolerance = tolerance();
        } else {
            throw Error(where, "expected the kind 'surface', 'planar' or 'trimmed'");
        }
        t.faces.push_back(std::move(record));
    }
    return t;
}

// A construction record as (kind, numbers): the fields of its parameters in declaration order.
py::tuple construction_state(const Construction& c) {
    std::vector<double> n;
    auto add = [&](const Vec3& v) { n.insert(n.end(), {v.x, v.y, v.z}); };
    if (const auto* p = c.get<Construction::Cylinder>()) add(p->center), add(p->axis), n.insert(n.end(), {p->radius, p->height});
    else if (const auto* p = c.get<Construction::Cone>())
        add(p->center), add(p->axis), n.insert(n.end(), {p->radius1, p->radius2, p->height});
    else if (const auto* p = c.get<Construction::Sphere>()) add(p->center), n.push_back(p->radius);
    else if (const auto* p = c.get<Construction::Torus>())
        add(p->center), add(p->axis), n.insert(n.end(), {p->major_radius, p->minor_radius});
    else if (const auto* p = c.get<Construction::Revolution>()) add(p->axis_point), add(p->axis_dir), n.push_back(p->angle_deg);
    else if (const auto* p = c.get<Construction::Extrusion>()) add(p->direction), n.push_back(p->distance);
    return py::make_tuple(std::string(c.kind()), number_tuple(n));
}

Construction construction_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 2, at);
    const std::string kind = py::isinstance<py::str>(items[0]) ? items[0].cast<std::string>() : "";
    const std::vector<double> n = to_doubles(items[1], at + ".parameters");
    const std::size_t sizes[] = {0, 8, 9, 4, 8, 7, 4};
    const char* kinds[] = {"none", "cylinder", "cone", "sphere", "torus", "revolution", "extrusion"};
    std::size_t index = 0;
    while (index < std::size(kinds) && kind != kinds[index]) ++index;
    if (index == std::size(kinds)) throw Error(at + ".kind", "unknown kind '" + kind + "'");
    if (n.size() != sizes[index]) throw Error(at + ".parameters", "expected " + std::to_string(sizes[index]) + " numbers");
    const auto v = [&](std::size_t k) { return Vec3{n[k], n[k + 1], n[k + 2]}; };
    switch (index) {
        case 1: return Construction::Cylinder{v(0), v(3), n[6], n[7]};
        case 2: return Construction::Cone{v(0), v(3), n[6], n[7], n[8]};
        case 3: return Construction::Sphere{v(0), n[3]};
        case 4: return Construction::Torus{v(0), v(3), n[6], n[7]};
        case 5: return Construction::Revolution{v(0), v(3), n[6]};
        case 6: return Construction::Extrusion{v(0), n[3]};
        default: return {};
    }
}

py::tuple state_of(const Face& f) { return py::make_tuple(tables_state(tables_of(std::span<const Face>(&f, 1)))); }
py::tuple state_of(const Solid& s) {
    return py::make_tuple(tables_state(tables_of(s.faces())), construction_state(s.construction()), s.name());
}
py::tuple state_of(const Mesh& m) {
    std::vector<double> vertices;
    for (const Vec3& p : m.vertices) vertices.insert(vertices.end(), {p.x, p.y, p.z});
    py::tuple triangles(3 * m.triangles.size());
    for (std::size_t k = 0; k < m.triangles.size(); ++k)
        for (std::size_t c = 0; c < 3; ++c) triangles[3 * k + c] = m.triangles[k][c];
    return py::make_tuple(number_tuple(vertices), triangles);
}

Face face_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 1, at);
    auto faces = faces_of(tables_from(items[0], at));
    if (faces.size() != 1) throw Error(at, "expected the tables of one face");
    return std::move(faces.front());
}
// The construction record is checked against the faces (construction_check.hpp): a crafted pickle must not
// give a cube a sphere's exact volume, nor keep it through a re-pickling.
Solid solid_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 2, at, 3);
    std::vector<Face> faces = faces_of(tables_from(items[0], at));
    Construction construction = construction_from(items[1], at + ".construction");
    require_describes(construction, faces, at + ".construction");
    Solid solid(std::move(faces), std::move(construction));
    if (items.size() == 3) {
        if (!py::isinstance<py::str>(items[2])) throw Error(at + ".name", "expected a str");
        solid.set_name(items[2].cast<std::string>());
    }
    return solid;
}
Mesh mesh_from(py::handle state, const std::string& at) {
    const auto items = state_items(state, 2, at);
    const auto coordinates = to_doubles(items[0], at + ".vertices");
    const auto indices = to_doubles(items[1], at + ".triangles");
    if (coordinates.size() % 3 != 0 || indices.size() % 3 != 0) throw Error(at, "expected triples");
    Mesh mesh;
    for (std::size_t k = 0; k < coordinates.size(); k += 3)
        mesh.vertices.push_back({coordinates[k], coordinates[k + 1], coordinates[k + 2]});
    // As the constructor: a NaN vertex restored would be a Mesh the constructor refuses.
    require_finite_vertices(mesh.vertices, at + ".vertices");
    for (std::size_t k = 0; k < indices.size(); k += 3) {
        std::array<std::uint32_t, 3> t{};
        for (std::size_t c = 0; c < 3; ++c) {
            const double i = indices[k + c];
            if (!(i >= 0 && i < static_cast<double>(mesh.vertices.size())) || i != static_cast<double>(static_cast<std::uint32_t>(i)))
                throw Error(at + ".triangles", "vertex index out of range");
            t[c] = static_cast<std::uint32_t>(i);
        }
        mesh.triangles.push_back(t);
    }
    return mesh;
}

// ---- registration -----------------------------------------------------------------------------------

py::object restore(const std::string& type, const py::object& state) {
    const std::string at = "state";
    if (type == "BezierCurve") return py::cast(bezier_curve_from(state, at));
    if (type == "NurbsCurve") return py::cast(nurbs_curve_from(state, at));
    if (type == "BezierSurface") return py::cast(bezier_surface_from(state, at));
    if (type == "NurbsSurface") return py::cast(nurbs_surface_from(state, at));
    if (type == "Face") return py::cast(face_from(state, at));
    if (type == "Solid") return py::cast(solid_from(state, at));
    if (type == "Mesh") return py::cast(mesh_from(state, at));
    throw Error("type", "unknown ratbez type '" + type + "'");
}

template <class T>
void def_copy_and_pickle(const char* type) {
    reopen<T>()
        .def("__reduce__",
             [type](const T& x) {
                 return py::make_tuple(py::module_::import("ratbez").attr("_restore"), py::make_tuple(type, state_of(x)));
             })
        .def("__copy__", [](const T& x) { return T(x); })
        .def("__deepcopy__", [](const T& x, const py::object&) { return T(x); }, py::arg("memo"));
}

// == and hash by the exact data: the degrees, knots and homogeneous points. The rational flag (the last
// item of the state) is not part of the value: the same points and weights are the same curve.
template <class T>
py::tuple value_of(const T& x) {
    const py::tuple state = state_of(x);
    return state[py::slice(0, static_cast<py::ssize_t>(py::len(state)) - 1, 1)];
}

template <class T>
void def_value_equality() {
    reopen<T>()
        .def("__eq__", [](const T& a, const T& b) { return value_of(a).equal(value_of(b)); }, py::is_operator())
        .def("__ne__", [](const T& a, const T& b) { return value_of(a).not_equal(value_of(b)); }, py::is_operator())
        .def("__hash__", [](const T& x) { return py::hash(value_of(x)); });
}

}  // namespace

void bind_values(py::module_& m) {
    m.def("_restore_state", &restore, py::arg("type"), py::arg("state"),
          "Rebuild a pickled ratbez object from its type name and exact state (what __reduce__ returns).");
    // pickle stores functions by reference, module and name; a pybind11 function's __self__ is a capsule,
    // which pickle cannot reference, so the function pickles name is a Python one that calls it.
    py::exec(R"(
def _restore(type, state):
    """Rebuild a pickled ratbez object: ratbez._restore_state(type, state)."""
    return _restore_state(type, state)
)",
             m.attr("__dict__"));
    def_copy_and_pickle<BezierCurve>("BezierCurve");
    def_copy_and_pickle<NurbsCurve>("NurbsCurve");
    def_copy_and_pickle<BezierSurface>("BezierSurface");
    def_copy_and_pickle<NurbsSurface>("NurbsSurface");
    def_copy_and_pickle<Face>("Face");
    def_copy_and_pickle<Solid>("Solid");
    def_copy_and_pickle<Mesh>("Mesh");
    def_value_equality<BezierCurve>();
    def_value_equality<NurbsCurve>();
    def_value_equality<BezierSurface>();
    def_value_equality<NurbsSurface>();
}

}  // namespace ratbez::python
