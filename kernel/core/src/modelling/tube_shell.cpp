// The tube B-rep shared by extrude, loft and sweep; see tube_shell.hpp.
#include "modelling/tube_shell.hpp"

#include "brep/brep_build.hpp"
#include "ratbez/frame.hpp"

namespace ratbez::detail {

namespace {

// The lateral faces of one loop and the loop's edges at both ends of the tube.
struct TubeLoop {
    std::vector<Face> faces;
    std::vector<EdgePtr> start_edges, end_edges;
    VertexPtr first_start, first_end;
};

TubeLoop tube_loop(const std::vector<NurbsSurface>& lateral, bool capped) {
    const std::size_t m = lateral.size();
    // Corner vertices: start[k] = lateral[k]'s (u_min, v_min) corner, end[k] its (u_min, v_max) corner.
    std::vector<VertexPtr> start, end;
    for (const NurbsSurface& s : lateral) {
        start.push_back(make_vertex(project(s.homogeneous_point(0, 0))));
        end.push_back(capped ? make_vertex(project(s.homogeneous_point(0, s.columns() - 1))) : start.back());
    }
    TubeLoop loop;
    std::vector<EdgePtr> joint_edges;
    for (std::size_t k = 0; k < m; ++k) {
        const NurbsSurface& s = lateral[k];
        const std::size_t next = (k + 1) % m;
        loop.start_edges.push_back(make_edge(s.isocurve_v(s.domain_v().min), start[k], start[next]));
        loop.end_edges.push_back(capped ? make_edge(s.isocurve_v(s.domain_v().max), end[k], end[next])
                                        : loop.start_edges.back());
        joint_edges.push_back(make_edge(s.isocurve_u(s.domain_u().min), start[k], end[k]));
    }
    for (std::size_t k = 0; k < m; ++k)
        loop.faces.push_back(Face::from_surface(
            lateral[k], {Coedge{loop.start_edges[k], false}, Coedge{joint_edges[(k + 1) % m], false},
                         Coedge{loop.end_edges[k], true}, Coedge{joint_edges[k], true}}));
    loop.first_start = start.front();
    loop.first_end = end.front();
    return loop;
}

}  // namespace

Solid tube_solid(const std::vector<std::vector<NurbsSurface>>& loops, const std::optional<CapNormals>& caps,
                 Construction construction) {
    std::vector<Face> faces;
    std::vector<std::vector<Coedge>> start_loops, end_loops;
    Vec3 start_origin{}, end_origin{};
    for (const std::vector<NurbsSurface>& lateral : loops) {
        TubeLoop loop = tube_loop(lateral, caps.has_value());
        for (Face& face : loop.faces) faces.push_back(std::move(face));
        if (start_loops.empty()) {
            start_origin = loop.first_start->point;
            end_origin = loop.first_end->point;
        }
        // The start cap runs every loop backwards (its outward normal points against the tube), the end cap
        // forwards; the outer loop comes first in both, as Face::planar wants.
        auto& start_loop = start_loops.emplace_back();
        auto& end_loop = end_loops.emplace_back();
        for (std::size_t k = loop.start_edges.size(); k-- > 0;) start_loop.push_back(Coedge{loop.start_edges[k], true});
        for (const EdgePtr& edge : loop.end_edges) end_loop.push_back(Coedge{edge, false});
    }
    if (caps) {
        const Frame start = frame_from_axis(start_origin, caps->start);
        const Frame end = frame_from_axis(end_origin, caps->end);
        faces.push_back(Face::planar(Plane{start.origin, start.x_axis, start.y_axis, start.z_axis}, std::move(start_loops)));
        faces.push_back(Face::planar(Plane{end.origin, end.x_axis, end.y_axis, end.z_axis}, std::move(end_loops)));
    }
    return Solid(std::move(faces), std::move(construction));
}

}  // namespace ratbez::detail
