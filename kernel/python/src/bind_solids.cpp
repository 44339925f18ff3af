// Bindings of exact curves, primitive solids, sweeps, the B-rep (Solid, Face), meshes and tessellation.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <sstream>
#include <string>

#include "convert.hpp"
#include "python_progress.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/construction.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/error.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/properties.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::python {

namespace {

py::tuple origin() { return py::make_tuple(0.0, 0.0, 0.0); }
py::tuple z_axis() { return py::make_tuple(0.0, 0.0, 1.0); }

// The mesh's own tables as read-only numpy views: no copy on access, the Mesh object as the views' base
// (kept alive by them), and an edit raises instead of being silently lost on a copy.
py::array vertex_view(const py::object& self) {
    const Mesh& mesh = self.cast<const Mesh&>();
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three packed doubles");
    py::array_t<double> view({static_cast<py::ssize_t>(mesh.vertices.size()), py::ssize_t{3}},
                             {static_cast<py::ssize_t>(sizeof(Vec3)), static_cast<py::ssize_t>(sizeof(double))},
                             mesh.vertices.empty() ? nullptr : &mesh.vertices.front().x, self);
    py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return view;
}

py::array triangle_view(const py::object& self) {
    const Mesh& mesh = self.cast<const Mesh&>();
    static_assert(sizeof(mesh.triangles.front()) == 3 * sizeof(std::uint32_t), "triangles are packed index triples");
    py::array_t<std::uint32_t> view(
        {static_cast<py::ssize_t>(mesh.triangles.size()), py::ssize_t{3}},
        {static_cast<py::ssize_t>(3 * sizeof(std::uint32_t)), static_cast<py::ssize_t>(sizeof(std::uint32_t))},
        mesh.triangles.empty() ? nullptr : mesh.triangles.front().data(), self);
    py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return view;
}

// A mesh from Python tables; every index is checked, since Mesh itself trusts its triangles.
Mesh make_mesh(const py::object& vertices, const py::object& triangles) {
    Mesh mesh;
    mesh.vertices = to_points(vertices, "vertices");
    require_finite_vertices(mesh.vertices, "vertices");
    std::size_t index = 0;
    if (py::isinstance<py::str>(triangles) || !PySequence_Check(triangles.ptr()))
        throw Error("triangles", "expected a sequence of index triples");
    for (py::handle row : triangles) {
        const std::string name = "triangles[" + std::to_string(index) + "]";
        if (py::isinstance<py::str>(row) || !PySequence_Check(row.ptr()) || py::len(row) != 3)
            throw Error(name, "expected 3 vertex indices");
        std::array<std::uint32_t, 3> triangle{};
        for (std::size_t k = 0; k < 3; ++k) {
            const int vertex = to_int(row[py::int_(k)], name);
            if (vertex < 0 || static_cast<std::size_t>(vertex) >= mesh.vertices.size())
                throw Error(name, "vertex index " + std::to_string(vertex) + " is out of range [0, " +
                            std::to_string(mesh.vertices.size()) + ")");
            triangle[k] = static_cast<std::uint32_t>(vertex);
        }
        mesh.triangles.push_back(triangle);
        ++index;
    }
    return mesh;
}

// Solid.parameters: keyed by the Python arguments of the function that builds that kind, so that
// ratbez.cylinder(**s.parameters) builds s again (revolve and extrude take the profile besides).
py::dict construction_parameters(const Construction& construction) {
    py::dict parameters;
    const auto place = [&](const Vec3& center, const Vec3& axis) {
        parameters["center"] = to_tuple(center);
        parameters["axis"] = to_tuple(axis);
    };
    if (const auto* c = construction.get<Construction::Cylinder>()) {
        parameters["radius"] = c->radius;
        parameters["height"] = c->height;
        place(c->center, c->axis);
    } else if (const auto* k = construction.get<Construction::Cone>()) {
        parameters["radius1"] = k->radius1;
        parameters["radius2"] = k->radius2;
        parameters["height"] = k->height;
        place(k->center, k->axis);
    } else if (const auto* s = construction.get<Construction::Sphere>()) {
        parameters["radius"] = s->radius;
        parameters["center"] = to_tuple(s->center);
    } else if (const auto* t = construction.get<Construction::Torus>()) {
        parameters["major_radius"] = t->major_radius;
        parameters["minor_radius"] = t->minor_radius;
        place(t->center, t->axis);
    } else if (const auto* r = construction.get<Construction::Revolution>()) {
        parameters["axis_point"] = to_tuple(r->axis_point);
        parameters["axis_dir"] = to_tuple(r->axis_dir);
        parameters["angle"] = r->angle_deg;
    } else if (const auto* e = construction.get<Construction::Extrusion>()) {
        parameters["direction"] = to_tuple(e->direction);
        parameters["distance"] = e->distance;
    }
    return parameters;
}

NurbsCurve coedge_curve(const Coedge& coedge) {
    return coedge.reversed ? coedge.edge->curve.reversed() : coedge.edge->curve;
}

// The coedge in its face's (u, v), in the direction the loop runs it: a trimmed face's own p-curve; for a
// planar face the edge in the plane's coordinates, which are its patch's parameters (brep.hpp).
NurbsCurve coedge_pcurve(const Face& face, const Coedge& coedge) {
    if (coedge.pcurve) return coedge.reversed ? coedge.pcurve->reversed() : *coedge.pcurve;
    const Plane& plane = face.plane();
    const NurbsCurve& curve = coedge.edge->curve;
    std::vector<Vec4> points = curve.homogeneous_points();
    for (Vec4& p : points) {
        const Vec3 d = project(p) - plane.origin;
        p = Vec4{dot(d, plane.x_axis) * p.w, dot(d, plane.y_axis) * p.w, 0, p.w};
    }
    NurbsCurve flat = NurbsCurve::from_homogeneous(curve.degree(), curve.knots(), std::move(points), curve.is_rational());
    return coedge.reversed ? flat.reversed() : flat;
}

const char* kind_name(const Face& face) {
    switch (face.kind()) {
        case Face::Kind::planar: return "planar";
        case Face::Kind::trimmed: return "trimmed";
        default: return "surface";
    }
}

// A measurement of a solid (properties.hpp) from Python: the GIL released, Ctrl-C and `progress` polled.
template <double (*Measure)(const Solid&, const Progress&)>
double measured(const Solid& solid, const py::object& progress) {
    const Progress poll = python_progress(progress);
    py::gil_scoped_release release;
    return Measure(solid, poll);
}

}  // namespace

void bind_solids(py::module_& m) {
    m.def(
        "line_segment",
        [](const py::object& start, const py::object& end) {
            return line_segment(to_vec3(start, "start"), to_vec3(end, "end"));
        },
        py::arg("start"), py::arg("end"), "The straight segment from start to end as a degree-1 NurbsCurve.");
    m.def(
        "circle",
        [](double radius, const py::object& center, const py::object& normal) {
            return circle(radius, to_vec3(center, "center"), to_vec3(normal, "normal"));
        },
        py::arg("radius"), py::arg("center") = origin(), py::arg("normal") = z_axis(),
        "A full circle as a piecewise rational quadratic NurbsCurve, counterclockwise about normal.");
    m.def(
        "arc",
        [](double radius, double start_deg, double end_deg, const py::object& center, const py::object& normal) {
            return arc(radius, start_deg, end_deg, to_vec3(center, "center"), to_vec3(normal, "normal"));
        },
        py::arg("radius"), py::arg("start_deg"), py::arg("end_deg"), py::arg("center") = origin(),
        py::arg("normal") = z_axis(), "A circular arc from start_deg to end_deg as an exact NurbsCurve.");
    m.def(
        "ellipse_arc",
        [](double a, double b, double start_deg, double end_deg, const py::object& center, const py::object& normal) {
            return ellipse_arc(a, b, start_deg, end_deg, to_vec3(center, "center"), to_vec3(normal, "normal"));
        },
        py::arg("a"), py::arg("b"), py::arg("start_deg"), py::arg("end_deg"), py::arg("center") = origin(),
        py::arg("normal") = z_axis(), "An elliptical arc with semi-axes a and b as an exact NurbsCurve.");

    py::class_<Mesh>(m, "Mesh", "A triangle mesh: vertex table and outward triangles (right-hand rule).")
        .def(py::init(&make_mesh), py::arg("vertices"), py::arg("triangles"))
        .def_property_readonly("vertices", &vertex_view,
                               "N x 3 float64 array of the vertex coordinates: a read-only view of the mesh's own\n"
                               "table (no copy; np.array(mesh.vertices) for an editable one).")
        .def_property_readonly("triangles", &triangle_view,
                               "M x 3 uint32 array of vertex indices, outward by the right-hand rule: a read-only\n"
                               "view of the mesh's own table.")
        .def("is_closed", &Mesh::is_closed, "True when every edge is used by exactly two triangles, in opposite directions.")
        .def("volume", &Mesh::volume, "The enclosed volume by the divergence theorem (positive for an outward closed mesh).")
        .def("area", &Mesh::area, "The total triangle area (model units squared).")
        .def("__repr__", [](const Mesh& mesh) {
            return "<ratbez.Mesh vertices=" + std::to_string(mesh.vertices.size()) +
                   " triangles=" + std::to_string(mesh.triangles.size()) + ">";
        });

    py::class_<Face>(m, "Face",
                     "A face of a Solid: an untrimmed NURBS surface, a plane patch trimmed by loops, or any NURBS\n"
                     "surface trimmed by loops whose edges carry p-curves in its (u, v).")
        .def_property_readonly("kind", &kind_name,
                               "'surface' (an untrimmed NURBS surface), 'planar' (a plane patch trimmed by loops) or\n"
                               "'trimmed' (a NURBS surface trimmed by loops of edges with p-curves).")
        .def_property_readonly("surface", &Face::surface,
                               "The face's NurbsSurface; for a planar face the plane patch its loops trim; for a trimmed\n"
                               "face the surface its loops trim.")
        .def_property_readonly(
            "pcurves",
            [](const Face& f) {
                py::list loops;
                for (const auto& loop : f.loops()) {
                    py::list curves;
                    for (const auto& coedge : loop) curves.append(coedge_pcurve(f, coedge));
                    loops.append(curves);
                }
                return loops;
            },
            "The loops in the face's (u, v): for each curve of `loops`, the 2D NurbsCurve (z = 0) of the same\n"
            "boundary piece in the same direction (a trimmed face's p-curves; a planar face's loops in the\n"
            "plane's coordinates, which are its surface's parameters); [] for a surface face.")
        .def_property_readonly("tolerance", &Face::tolerance,
                               "How far the face's boundary may keep from its surface: 0 for exact constructions, the\n"
                               "file's tolerance (or a fitted p-curve's error) for imported faces.")
        .def_property_readonly(
            "loops",
            [](const Face& f) {
                py::list loops;
                for (const auto& loop : f.loops()) {
                    py::list curves;
                    for (const auto& coedge : loop) curves.append(coedge_curve(coedge));
                    loops.append(curves);
                }
                return loops;
            },
            "Boundary loops of a planar or trimmed face (the outer loop first, then holes), each a list of the\n"
            "3D NurbsCurve of its edges in loop order (a pole as a curve of one point); [] for a surface face.")
        .def("point", [](const Face& f, double u, double v) { return to_tuple(f.point(u, v)); }, py::arg("u"), py::arg("v"),
             "The surface point S(u, v) as (x, y, z).")
        .def("normal", [](const Face& f, double u, double v) { return to_tuple(f.normal(u, v)); }, py::arg("u"),
             py::arg("v"), "The outward unit normal.")
        .def("__repr__", [](const Face& f) { return std::string("<ratbez.Face ") + kind_name(f) + ">"; });

    py::class_<Solid>(m, "Solid", "A solid bounded by closed shells of exact NURBS faces (an outer shell and any voids).")
        .def_property_readonly("faces", &Solid::faces, "The faces of its shells (list of Face).")
        .def_property_readonly(
            "shells", [](const Solid& s) { return s.shells(); },
            "The indices into `faces` of each shell: the outer shell first, then the voids (whose normals point\n"
            "into the void, out of the material).")
        .def_property(
            "name", [](const Solid& s) { return s.name(); }, [](Solid& s, std::string name) { s.set_name(std::move(name)); },
            "What the file it was read from calls it (a STEP product's name), or ''; free to set.")
        .def_property_readonly(
            "kind", [](const Solid& s) { return std::string(s.construction().kind()); },
            "What the solid was built as: 'cylinder', 'cone', 'sphere', 'torus', 'revolution', 'extrusion', "
            "or 'none' (assembled from faces).")
        .def_property_readonly(
            "parameters", [](const Solid& s) { return construction_parameters(s.construction()); },
            "The arguments it was built with, keyed as the building function's (axes and directions as unit "
            "vectors): {'radius': 2.0, 'center': (0.0, 0.0, 0.0)} for a sphere; revolve's and extrude's "
            "without the profile; {} for 'none'.")
        .def_property_readonly(
            "exact_volume", [](const Solid& s) { return s.construction().exact_volume(); },
            "The closed-form volume of a cylinder, cone, sphere or torus; None for other kinds.")
        .def_property_readonly(
            "exact_area", [](const Solid& s) { return s.construction().exact_area(); },
            "The closed-form surface area of a cylinder, cone, sphere or torus; None for other kinds.")
        .def("volume", &measured<enclosed_volume>, py::arg("progress") = py::none(),
             (std::string("The enclosed volume (model units cubed), by adaptive cubature of the exact faces to about\n"
                          "1e-14 relative (milliseconds for an ordinary solid).\n\n") + progress_doc).c_str())
        .def("area", &measured<surface_area>, py::arg("progress") = py::none(),
             (std::string("The surface area (model units squared), by adaptive cubature of the exact faces to about\n"
                          "1e-14 relative.\n\n") + progress_doc).c_str())
        .def("euler_characteristic", &Solid::euler_characteristic, "V - E + F of the B-rep (2 for a sphere-like shell).")
        .def(
            "bounding_box",
            [](const Solid& s) {
                const auto box = s.bounding_box();
                return py::make_tuple(to_tuple(box.min), to_tuple(box.max));
            },
            "((xmin, ymin, zmin), (xmax, ymax, zmax)): the box of the faces' control points (a rational\n"
            "curve or surface lies in the convex hull of its control points), so it contains the solid, but\n"
            "it is larger than the tight box where control points lie off the surface (the corner points of a\n"
            "circle's quarter arcs); cheap, no evaluation. For a tight box, tessellate and take the mesh's\n"
            "vertices' extremes (within the tolerance).")
        .def("__repr__", [](const Solid& s) {
            return "<ratbez.Solid " + (s.name().empty() ? std::string() : "'" + s.name() + "' ") +
                   "faces=" + std::to_string(s.faces().size()) + ">";
        });

    m.def("default_tolerance", &default_tolerance, py::arg("solid"),
          "The tessellation tolerance used when none is given: 1e-3 of the bounding-box diagonal, or the largest\n"
          "Face.tolerance of a solid read from a file if that is more (no mesh follows that face closer).");

    m.def(
        "cylinder",
        [](double radius, double height, const py::object& center, const py::object& axis) {
            return cylinder(radius, height, to_vec3(center, "center"), to_vec3(axis, "axis"));
        },
        py::arg("radius"), py::arg("height"), py::arg("center") = origin(), py::arg("axis") = z_axis(),
        "A cylinder; center is the base center.");
    m.def(
        "cone",
        [](double radius1, double radius2, double height, const py::object& center, const py::object& axis) {
            return cone(radius1, radius2, height, to_vec3(center, "center"), to_vec3(axis, "axis"));
        },
        py::arg("radius1"), py::arg("radius2"), py::arg("height"), py::arg("center") = origin(),
        py::arg("axis") = z_axis(), "A cone or frustum; center is the base center, radius2 may be 0 (apex).");
    m.def(
        "sphere", [](double radius, const py::object& center) { return sphere(radius, to_vec3(center, "center")); },
        py::arg("radius"), py::arg("center") = origin(), "A sphere of radius > 0 about center, exact rational faces.");
    m.def(
        "torus",
        [](double major_radius, double minor_radius, const py::object& center, const py::object& axis) {
            return torus(major_radius, minor_radius, to_vec3(center, "center"), to_vec3(axis, "axis"));
        },
        py::arg("major_radius"), py::arg("minor_radius"), py::arg("center") = origin(), py::arg("axis") = z_axis(),
        "A torus about axis through center: the tube of minor_radius around the circle of major_radius\n"
        "(major_radius > minor_radius > 0).");
    m.def(
        "revolve",
        [](const py::object& profile, const py::object& axis_point, const py::object& axis_dir, double angle) {
            try {
                return revolve(to_profile(profile, "profile"), to_vec3(axis_point, "axis_point"),
                               to_vec3(axis_dir, "axis_dir"), angle);
            } catch (const Error& e) {
                throw e.renamed("angle_deg", "angle");  // the kernel's name for what Python calls angle
            }
        },
        py::arg("profile"), py::arg("axis_point") = origin(), py::arg("axis_dir") = z_axis(), py::arg("angle") = 360.0,
        "Revolve a profile (BezierCurve, NurbsCurve or a list of them joined end to end) by angle degrees.");
    m.def(
        "extrude",
        [](const py::object& profile, const py::object& direction, double distance, const py::object& holes) {
            std::vector<Profile> hole_profiles;
            if (!holes.is_none()) {
                if (!py::isinstance<py::list>(holes) && !py::isinstance<py::tuple>(holes))
                    fail("holes", "expected a list of profiles");
                std::size_t index = 0;
                for (py::handle hole : holes) hole_profiles.push_back(to_profile(hole, "holes[" + std::to_string(index++) + "]"));
            }
            return extrude(to_profile(profile, "profile"), to_vec3(direction, "direction"), distance, hole_profiles);
        },
        py::arg("profile"), py::arg("direction"), py::arg("distance"), py::arg("holes") = py::none(),
        "Sweep a closed planar profile by distance along direction; holes: closed profiles inside it (a list,\n"
        "each a curve or a list of curves joined end to end) that become holes through the prism.");
}

}  // namespace ratbez::python
