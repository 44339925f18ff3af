// The tube B-rep shared by extrude, loft and sweep; see tube_shell.hpp.
#include "tube_shell.hpp"

#include "geometry_internal.hpp"
#include "ratbez/frame.hpp"

namespace ratbez::detail {

Solid tube_solid(const std::vector<NurbsSurface>& lateral, const std::optional<CapNormals>& caps) {
    const std::size_t m = lateral.size();
    // Corner vertices: bottom[k] = lateral[k]'s (u_min, v_min) corner, top[k] its (u_min, v_max) corner.
    std::vector<VertexPtr> bottom, top;
    for (const NurbsSurface& s : lateral) {
        bottom.push_back(make_vertex(project(s.homogeneous_point(0, 0))));
        top.push_back(caps ? make_vertex(project(s.homogeneous_point(0, s.columns() - 1))) : bottom.back());
    }
    std::vector<EdgePtr> bottom_edges, top_edges, joint_edges;
    for (std::size_t k = 0; k < m; ++k) {
        const NurbsSurface& s = lateral[k];
        const std::size_t next = (k + 1) % m;
        bottom_edges.push_back(make_edge(s.isocurve_v(s.domain_v().min), bottom[k], bottom[next]));
        top_edges.push_back(caps ? make_edge(s.isocurve_v(s.domain_v().max), top[k], top[next]) : bottom_edges.back());
        joint_edges.push_back(make_edge(s.isocurve_u(s.domain_u().min), bottom[k], top[k]));
    }
    std::vector<Face> faces;
    for (std::size_t k = 0; k < m; ++k)
        faces.push_back(Face::from_surface(lateral[k], {Coedge{bottom_edges[k], false}, Coedge{joint_edges[(k + 1) % m], false},
                                                        Coedge{top_edges[k], true}, Coedge{joint_edges[k], true}}));
    if (caps) {
        // The start cap runs the profile backwards (its outward normal points against the tube), the end
        // cap forwards.
        std::vector<Coedge> start_loop, end_loop;
        for (std::size_t k = m; k-- > 0;) start_loop.push_back(Coedge{bottom_edges[k], true});
        for (std::size_t k = 0; k < m; ++k) end_loop.push_back(Coedge{top_edges[k], false});
        const Frame start = frame_from_axis(bottom.front()->point, caps->start);
        const Frame end = frame_from_axis(top.front()->point, caps->end);
        faces.push_back(Face::planar(Plane{start.origin, start.x_axis, start.y_axis, start.z_axis}, {start_loop}));
        faces.push_back(Face::planar(Plane{end.origin, end.x_axis, end.y_axis, end.z_axis}, {end_loop}));
    }
    return Solid(std::move(faces));
}

}  // namespace ratbez::detail
