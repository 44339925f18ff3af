// The convex hull of a mesh's vertices (ratbez/convex_hull.hpp), from CGAL's 3D Delaunay triangulation of them: its
// facets on the infinite vertex are the hull's, triangulated. convex_hull_3 would do too, but it orders its
// work by vertex addresses (a std::map of handles), so the same mesh came back with another triangulation of
// its flat facets from run to run; the Delaunay triangulation, fed in a Hilbert order (no random shuffle) and
// perturbed symbolically where points are cospherical, gives one answer for one input.

#include "ratbez/convex_hull.hpp"

#include "math/vector_angle.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <vector>

namespace ratbez {

namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

Point point_of(const Mesh& mesh, std::uint32_t k) {
    const Vec3& v = mesh.vertices[k];
    return Point(v.x, v.y, v.z);
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) { return (static_cast<std::uint64_t>(a) << 32) | b; }

// The mesh with its reflex edges flipped until none is left (Lawson's flips, on the surface): a flip of the
// edge ab between triangles abc and bad to cd adds the tetrahedron abcd to the enclosed volume, so the flips
// end. A mesh whose vertices all lie on its hull comes out as that hull in a few flips per reflex edge (the
// straddled sphere: its non-planar quadrilaterals cut along the other diagonal), in the mesh's own order and
// far sooner than a hull from scratch; none when a vertex lies inside (no flip lifts it) or a flip would
// make an edge twice.
std::optional<Mesh> flipped_convex(Mesh mesh) {
    auto& triangles = mesh.triangles;
    std::unordered_map<std::uint64_t, std::uint32_t> owner;  // directed edge -> its triangle
    owner.reserve(3 * triangles.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (int i = 0; i < 3; ++i) owner[edge_key(triangles[t][i], triangles[t][(i + 1) % 3])] = t;
    const auto third = [&](std::uint32_t t, std::uint32_t a, std::uint32_t b) {
        for (const std::uint32_t k : triangles[t])
            if (k != a && k != b) return k;
        return a;
    };
    std::vector<std::uint64_t> queue;
    for (const auto& [key, t] : owner) queue.push_back(key);
    std::sort(queue.begin(), queue.end());  // the order of the flips, not of the hash table
    std::size_t flips = 0;
    const std::size_t max_flips = 20 * triangles.size() + 100;
    while (!queue.empty()) {
        const std::uint64_t key = queue.back();
        queue.pop_back();
        const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
        const auto first = owner.find(edge_key(a, b)), second = owner.find(edge_key(b, a));
        if (first == owner.end() || second == owner.end()) continue;  // flipped away meanwhile
        const std::uint32_t t1 = first->second, t2 = second->second;
        const std::uint32_t c = third(t1, a, b), d = third(t2, a, b);
        if (CGAL::orientation(point_of(mesh, a), point_of(mesh, b), point_of(mesh, c), point_of(mesh, d)) != CGAL::POSITIVE)
            continue;
        if (c == d || owner.count(edge_key(c, d)) || owner.count(edge_key(d, c)) || ++flips > max_flips) return std::nullopt;
        // abc + bad -> adc + dbc: the quadrilateral a d b c keeps its boundary and its orientation.
        for (const std::uint64_t gone : {edge_key(a, b), edge_key(b, a), edge_key(b, c), edge_key(c, a), edge_key(a, d), edge_key(d, b)})
            owner.erase(gone);
        triangles[t1] = {a, d, c};
        triangles[t2] = {d, b, c};
        for (const std::uint32_t t : {t1, t2})
            for (int i = 0; i < 3; ++i) owner[edge_key(triangles[t][i], triangles[t][(i + 1) % 3])] = t;
        for (const std::uint64_t again : {edge_key(a, d), edge_key(d, b), edge_key(b, c), edge_key(c, a)}) queue.push_back(again);
    }
    // No edge is reflex; but where the mesh is flat up to rounding (a pole in the plane of the ring around it)
    // coplanar triangles count as convex, and a fan can fold over its neighbours there. A convex surface's
    // angles around a vertex sum to at most a full turn: a vertex over it is such a fold.
    std::vector<double> turn(mesh.vertices.size(), 0.0);
    for (const auto& t : triangles)
        for (int i = 0; i < 3; ++i) {
            const Vec3 &p = mesh.vertices[t[i]], &q = mesh.vertices[t[(i + 1) % 3]], &r = mesh.vertices[t[(i + 2) % 3]];
            turn[t[i]] += detail::angle_between(q - p, r - p);
        }
    for (const double sum : turn)
        if (sum > 2 * std::numbers::pi * (1 + 1e-9)) return std::nullopt;
    return mesh;  // every edge was checked, and again whenever a flip changed its triangles: none is reflex
}

}  // namespace

Mesh convex_hull(const Mesh& mesh) {
    if (std::optional<Mesh> flipped = flipped_convex(mesh)) return *std::move(flipped);
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
    using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<VertexBase>>;

    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) points.emplace_back(v.x, v.y, v.z);
    std::vector<std::size_t> order(points.size());  // the property map's key type
    std::iota(order.begin(), order.end(), std::size_t{0});
    using Traits = CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::Pointer_property_map<Point>::type>;
    CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(points)));

    Delaunay triangulation;
    Delaunay::Vertex_handle hint;
    for (const std::size_t k : order) {
        hint = triangulation.insert(points[k], hint);
        hint->info() = static_cast<std::uint32_t>(k);  // a repeated point keeps one of its indices
    }

    // Each cell on the infinite vertex holds one hull facet, opposite it; oriented so that the finite cell
    // across it (inside the hull, of positive volume) lies behind it.
    std::vector<std::array<std::uint32_t, 3>> facets;
    std::vector<Delaunay::Cell_handle> cells;
    triangulation.incident_cells(triangulation.infinite_vertex(), std::back_inserter(cells));
    for (const Delaunay::Cell_handle cell : cells) {
        const int infinite = cell->index(triangulation.infinite_vertex());
        const Delaunay::Vertex_handle a = cell->vertex((infinite + 1) & 3), b = cell->vertex((infinite + 2) & 3),
                                      c = cell->vertex((infinite + 3) & 3);
        const Delaunay::Cell_handle inside = cell->neighbor(infinite);
        const Delaunay::Vertex_handle d = inside->vertex(inside->index(cell));
        const bool outward = CGAL::orientation(a->point(), b->point(), c->point(), d->point()) == CGAL::NEGATIVE;
        facets.push_back(outward ? std::array{a->info(), b->info(), c->info()} : std::array{a->info(), c->info(), b->info()});
    }

    // The vertices in the mesh's order, the triangles each from its lowest vertex, sorted: one output per input.
    constexpr std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> renumbered(points.size(), unused);
    for (const auto& facet : facets)
        for (const std::uint32_t k : facet) renumbered[k] = 0;
    Mesh out;
    for (std::size_t k = 0; k < points.size(); ++k)
        if (renumbered[k] != unused) {
            renumbered[k] = static_cast<std::uint32_t>(out.vertices.size());
            out.vertices.push_back(mesh.vertices[k]);  // the input's own doubles
        }
    out.triangles.reserve(facets.size());
    for (auto facet : facets) {
        for (std::uint32_t& k : facet) k = renumbered[k];
        std::rotate(facet.begin(), std::min_element(facet.begin(), facet.end()), facet.end());
        out.triangles.push_back(facet);
    }
    std::sort(out.triangles.begin(), out.triangles.end());
    return out;
}

bool is_convex_mesh(const Mesh& mesh) {
    std::unordered_map<std::uint64_t, std::uint32_t> far_vertex;  // directed edge (a, b) -> its triangle's third
    far_vertex.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        for (int i = 0; i < 3; ++i) far_vertex.emplace(edge_key(t[i], t[(i + 1) % 3]), t[(i + 2) % 3]);
    for (const auto& t : mesh.triangles)
        for (int i = 0; i < 3; ++i) {
            const auto twin = far_vertex.find(edge_key(t[(i + 1) % 3], t[i]));
            if (twin == far_vertex.end()) return false;  // open: no convex solid's mesh
            if (CGAL::orientation(point_of(mesh, t[0]), point_of(mesh, t[1]), point_of(mesh, t[2]), point_of(mesh, twin->second)) ==
                CGAL::POSITIVE)
                return false;
        }
    return true;
}

}  // namespace ratbez
