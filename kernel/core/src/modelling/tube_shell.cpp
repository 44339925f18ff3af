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

// bands[b][k]: band b along the tube, piece k around it. Rows of corner vertices and ring edges between the
// bands (row b is band b's v_min boundary, the last row the last band's v_max, or row 0 again on a closed
// tube), and in each band the joint edges between its pieces.
TubeLoop tube_loop(const std::vector<std::vector<NurbsSurface>>& bands, bool capped) {
    const std::size_t m = bands.front().size(), rows = bands.size() + 1;
    // corner[r][k]: piece k's (u_min, v_min) corner in band r; the last row the last band's (u_min, v_max) corners.
    std::vector<std::vector<VertexPtr>> corner(rows);
    for (std::size_t r = 0; r + 1 < rows; ++r)
        for (const NurbsSurface& s : bands[r]) corner[r].push_back(make_vertex(project(s.homogeneous_point(0, 0))));
    for (const NurbsSurface& s : bands.back())
        corner.back().push_back(capped ? make_vertex(project(s.homogeneous_point(0, s.columns() - 1)))
                                       : corner.front()[corner.back().size()]);
    // ring[r][k]: along piece k at row r, from the v_min side of band r's piece (the last row: v_max of the last).
    std::vector<std::vector<EdgePtr>> ring(rows);
    for (std::size_t r = 0; r < rows; ++r)
        for (std::size_t k = 0; k < m; ++k) {
            const std::size_t next = (k + 1) % m;
            if (r + 1 < rows) {
                const NurbsSurface& s = bands[r][k];
                ring[r].push_back(make_edge(s.isocurve_v(s.domain_v().min), corner[r][k], corner[r][next]));
            } else {
                const NurbsSurface& s = bands.back()[k];
                ring[r].push_back(capped ? make_edge(s.isocurve_v(s.domain_v().max), corner[r][k], corner[r][next])
                                         : ring.front()[k]);
            }
        }
    TubeLoop loop;
    for (std::size_t b = 0; b < bands.size(); ++b) {
        std::vector<EdgePtr> joints;
        for (std::size_t k = 0; k < m; ++k) {
            const NurbsSurface& s = bands[b][k];
            joints.push_back(make_edge(s.isocurve_u(s.domain_u().min), corner[b][k], corner[b + 1][k]));
        }
        for (std::size_t k = 0; k < m; ++k)
            loop.faces.push_back(Face::from_surface(
                bands[b][k], {Coedge{ring[b][k], false}, Coedge{joints[(k + 1) % m], false},
                              Coedge{ring[b + 1][k], true}, Coedge{joints[k], true}}));
    }
    loop.start_edges = ring.front();
    loop.end_edges = ring.back();
    loop.first_start = corner.front().front();
    loop.first_end = corner.back().front();
    return loop;
}

}  // namespace

Solid tube_solid(const std::vector<std::vector<NurbsSurface>>& loops, const std::optional<CapNormals>& caps,
                 Construction construction) {
    std::vector<TubeBands> banded;
    for (const std::vector<NurbsSurface>& lateral : loops) banded.push_back({lateral});
    return tube_solid_in_bands(banded, caps, std::move(construction));
}

Solid tube_solid_in_bands(const std::vector<TubeBands>& loops, const std::optional<CapNormals>& caps, Construction construction) {
    std::vector<Face> faces;
    std::vector<std::vector<Coedge>> start_loops, end_loops;
    Vec3 start_origin{}, end_origin{};
    for (const TubeBands& bands : loops) {
        TubeLoop loop = tube_loop(bands, caps.has_value());
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
