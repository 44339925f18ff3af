// The only translation unit that includes CGAL (it costs about 11 s to compile; keep it that way).
#include "ratbez/export/mesh_checks.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ratbez/error.hpp"
#include "ratbez/mesh_welding.hpp"
#include "ratbez/mesh_topology.hpp"

namespace ratbez::exporter {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Polygon = std::array<std::size_t, 3>;

std::string format_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

std::string count_of(std::size_t n, const char* singular, const char* plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// Vertices with identical coordinates at different indices: the mesh was not welded, so CGAL (and
// OpenSCAD) would see a crack there even when the surface looks closed.
std::size_t count_duplicate_vertices(const std::vector<Vec3>& vertices) {
    const std::vector<std::uint32_t> first = first_at_same_place(vertices);
    std::size_t duplicates = 0;
    for (std::size_t i = 0; i < first.size(); ++i) duplicates += first[i] != i;
    return duplicates;
}

// The volume of the axis-aligned bounding box of the given vertices: the scale of "no volume".
template <class Indices>
double bounding_box_volume(const std::vector<Vec3>& vertices, const Indices& indices) {
    auto first = std::begin(indices);
    if (first == std::end(indices)) return 0;
    Vec3 low = vertices[*first], high = low;
    for (const auto i : indices) {
        const Vec3& p = vertices[i];
        low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    const Vec3 size = high - low;
    return size.x * size.y * size.z;
}

// Connected components of the triangles (sharing a vertex index), by union-find on vertices.
std::vector<std::vector<std::size_t>> triangle_components(const Mesh& mesh) {
    std::vector<std::uint32_t> parent(mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), std::uint32_t{0});
    const auto root = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const auto& t : mesh.triangles) {
        parent[root(t[1])] = root(t[0]);
        parent[root(t[2])] = root(t[0]);
    }
    std::vector<std::size_t> component_of_root(mesh.vertices.size(), SIZE_MAX);
    std::vector<std::vector<std::size_t>> components;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        std::size_t& component = component_of_root[root(mesh.triangles[t][0])];
        if (component == SIZE_MAX) {
            component = components.size();
            components.emplace_back();
        }
        components[component].push_back(t);
    }
    return components;
}

// The winding number of a closed component about p: the solid angle its triangles subtend, over 4 pi (Van
// Oosterom and Strackee's formula per triangle): 1 inside an outward surface, -1 inside an inward one, 0 outside.
double winding_number(const Mesh& mesh, const std::vector<std::size_t>& component, const Vec3& p) {
    double total = 0;
    for (const std::size_t t : component) {
        const auto& tri = mesh.triangles[t];
        const Vec3 a = mesh.vertices[tri[0]] - p, b = mesh.vertices[tri[1]] - p, c = mesh.vertices[tri[2]] - p;
        const double la = norm(a), lb = norm(b), lc = norm(c);
        total += 2 * std::atan2(dot(a, cross(b, c)), la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb);
    }
    return total / (4 * std::numbers::pi);
}

// Outward orientation of a closed, consistently oriented, 2-manifold mesh: every connected component
// must enclose positive signed volume (divergence theorem, taken about the component's first vertex so
// that far-off meshes keep their digits), except a void: a component inside another, whose triangles face
// into the void, out of the material around it, and so enclose negative volume. Which components are voids
// is decided by nesting: at a vertex of a component, the winding numbers of all the others add up to 1 where
// it lies in material (a void's surface) and to 0 where it lies outside (an outer surface, or an island in a
// void). Unlike CGAL's is_outward_oriented, which inspects the extreme vertex only and asserts a
// non-degenerate neighbourhood there, this has no preconditions beyond valid indices and also refuses a
// closed surface folded flat onto itself (found by fuzz_mesh). "No volume" is measured against the
// component's bounding box, so that rounding on a flat mesh does not count. Returns the problem, or an empty
// string.
std::string orientation_problem(const Mesh& mesh) {
    const auto components = triangle_components(mesh);
    std::vector<double> volumes;
    for (const auto& component : components) {
        const Vec3 origin = mesh.vertices[mesh.triangles[component.front()][0]];
        double six_volume = 0;
        std::vector<std::uint32_t> corners;
        corners.reserve(component.size() * 3);
        for (const std::size_t t : component) {
            const auto& tri = mesh.triangles[t];
            const Vec3 a = mesh.vertices[tri[0]] - origin, b = mesh.vertices[tri[1]] - origin,
                       c = mesh.vertices[tri[2]] - origin;
            six_volume += dot(a, cross(b, c));
            corners.insert(corners.end(), tri.begin(), tri.end());
        }
        const double volume = six_volume / 6;
        const std::string which = component.size() == mesh.triangles.size()
                                      ? std::string()
                                      : " in a part of " + count_of(component.size(), "triangle", "triangles");
        if (std::abs(volume) <= 1e-12 * bounding_box_volume(mesh.vertices, corners))
            return "the closed surface encloses no volume (" + format_number(volume) + which +
                   "): it is flat or folded onto itself";
        volumes.push_back(volume);
    }
    if (std::all_of(volumes.begin(), volumes.end(), [](double v) { return v > 0; })) return {};
    for (std::size_t k = 0; k < components.size(); ++k) {
        if (volumes[k] > 0) continue;
        const Vec3 p = mesh.vertices[mesh.triangles[components[k].front()][0]];
        double nesting = 0;
        for (std::size_t other = 0; other < components.size(); ++other)
            if (other != k) nesting += winding_number(mesh, components[other], p);
        if (std::abs(nesting - 1) < 0.5) continue;  // a void in material: inward is right
        const std::string which = components.size() == 1 ? std::string()
                                                         : " in a part of " + count_of(components[k].size(), "triangle", "triangles");
        return "triangles face inward (the orientation is reversed" + which + ")";
    }
    return {};
}

// The surface's points as CGAL's self-intersection test reads them, polling `progress` every kReadsPerPoll
// reads. The test (box_self_intersection_d, then exact predicates on each candidate pair) has no hook of
// its own and reads points for every pair it tests, so this reaches it every few milliseconds; an
// exception thrown by the callback unwinds through it (does_self_intersect catches only its own).
class PollingPointMap {
public:
    using key_type = SurfaceMesh::Vertex_index;
    using value_type = Point;
    using reference = const Point&;
    using category = boost::readable_property_map_tag;
    static constexpr std::size_t kReadsPerPoll = 1 << 14;

    PollingPointMap(const SurfaceMesh& surface, const Progress& progress, double fraction, std::size_t& reads)
        : surface_(&surface), progress_(&progress), fraction_(fraction), reads_(&reads) {}

    friend reference get(const PollingPointMap& map, key_type v) {
        if (++*map.reads_ % kReadsPerPoll == 0) (*map.progress_)(map.fraction_);
        return map.surface_->point(v);
    }

private:
    const SurfaceMesh* surface_;
    const Progress* progress_;
    double fraction_;
    std::size_t* reads_;
};

using FacePair = std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>;

// The first two triangles CGAL's self-intersection test finds crossing (a degenerate one paired with itself), or
// none: does_self_intersect's own search, stopped at that pair by an exception out of the output iterator as it
// stops itself, so that a refusal can say where (a STEP part whose vertex lies 2e-7 from another face, which 3MF's
// float32 coordinates move through it).
template <class NamedParameters>
std::optional<FacePair> first_crossing(const SurfaceMesh& surface, const NamedParameters& parameters) {
    struct Found {
        FacePair faces;
    };
    try {
        const auto stop_at_first = [](const FacePair& pair) { throw Found{pair}; };
        PMP::self_intersections(surface, boost::make_function_output_iterator(stop_at_first), parameters);
    } catch (const Found& found) {
        return found.faces;
    }
    return std::nullopt;
}

// The middle of two triangles, as "(x, y, z)".
std::string place_of(const SurfaceMesh& surface, const FacePair& pair) {
    double sum[3] = {0, 0, 0};
    for (const auto f : {pair.first, pair.second})
        for (const auto v : CGAL::vertices_around_face(surface.halfedge(f), surface))
            for (int i = 0; i < 3; ++i) sum[i] += surface.point(v)[i] / 6;
    std::string text = "(";
    for (int i = 0; i < 3; ++i) text += format_number(sum[i]) + (i < 2 ? ", " : ")");
    return text;
}

// The Surface_mesh of a soup that mesh_topology found an oriented 2-manifold, face by face (what
// polygon_soup_to_polygon_mesh does in one call of over a second on 3M triangles), polling `progress`
// every 65,536 faces with the fraction where the conversion stands in check_mesh's progress.
void build_surface(const std::vector<Point>& points, const std::vector<Polygon>& polygons, SurfaceMesh& surface,
                   const Progress& progress) {
    constexpr std::size_t kFacesPerPoll = std::size_t{1} << 16;
    surface.reserve(static_cast<SurfaceMesh::size_type>(points.size()),
                    static_cast<SurfaceMesh::size_type>(3 * polygons.size() / 2),
                    static_cast<SurfaceMesh::size_type>(polygons.size()));
    for (const Point& p : points) surface.add_vertex(p);
    const auto vertex = [](std::size_t index) { return SurfaceMesh::Vertex_index(static_cast<SurfaceMesh::size_type>(index)); };
    for (std::size_t k = 0; k < polygons.size(); ++k) {
        if (progress && k % kFacesPerPoll == 0) progress(0.17);
        const Polygon& t = polygons[k];
        // Cannot fail on an oriented 2-manifold; a failure would be a bug in mesh_topology.
        if (surface.add_face(vertex(t[0]), vertex(t[1]), vertex(t[2])) == SurfaceMesh::null_face())
            throw Error("mesh", "internal error: triangle " + std::to_string(k) + " could not join the surface mesh");
    }
}

// Where the self-intersection test starts in the progress reported: it takes most of the time.
constexpr double kSelfIntersectionStart = 0.2;

}  // namespace

MeshReport check_mesh(const Mesh& mesh, const MeshCheckOptions& options) {
    const TriangleLimit limit = checked_triangle_limit(options);
    require(mesh.triangles.size() <= limit.triangles, "mesh", [&] {
        return "has " + std::to_string(mesh.triangles.size()) + " triangles, above " + limit.limit +
               "; use a coarser tolerance";
    });
    MeshReport report;

    // Structural problems first: CGAL's algorithms assume valid indices, finite points and no
    // degenerate index triples, so nothing further is meaningful without them.
    if (mesh.triangles.empty()) {
        report.problems.push_back("mesh has no triangles");
        return report;
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        if (!is_finite(mesh.vertices[i])) {
            report.problems.push_back("vertex " + std::to_string(i) + " is not finite");
            return report;
        }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        for (auto index : tri)
            if (index >= mesh.vertices.size()) {
                report.problems.push_back("triangle " + std::to_string(t) + " refers to vertex " +
                                          std::to_string(index) + ", past the " +
                                          std::to_string(mesh.vertices.size()) + " vertices");
                return report;
            }
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
            report.problems.push_back("triangle " + std::to_string(t) + " repeats a vertex");
            return report;
        }
    }

    report.volume = mesh.volume();  // only now: it reads the vertices the triangles name

    if (const auto duplicates = count_duplicate_vertices(mesh.vertices); duplicates > 0)
        report.problems.push_back(count_of(duplicates, "duplicate vertex", "duplicate vertices") +
                                  " (the mesh is not welded)");

    const MeshTopology topology = mesh_topology(mesh, progress_part(options.progress, 0.05, 0.12));
    report.closed = topology.closed();
    if (topology.border_edges > 0)
        report.problems.push_back("not closed: " + count_of(topology.border_edges, "border edge", "border edges"));

    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& p : mesh.vertices) points.emplace_back(p.x, p.y, p.z);
    std::vector<Polygon> polygons;
    polygons.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});

    // A soup that is already an oriented 2-manifold converts directly (mesh_topology decides what CGAL's
    // is_polygon_soup_a_polygon_mesh would, in linear time, polling, and about 7x faster on 3M triangles).
    // Otherwise orient_polygon_soup tells the two failures apart: it succeeds without duplicating points
    // when only the orientation was inconsistent, and returns false when it had to split non-manifold
    // edges or vertices.
    if (options.progress) options.progress(0.12);
    bool consistently_oriented = topology.oriented_manifold();
    if (consistently_oriented) {
        report.manifold = true;
    } else {
        report.manifold = PMP::orient_polygon_soup(points, polygons);
        if (!report.manifold || topology.non_manifold_edges > 0) {
            report.manifold = false;
            std::string what = "not 2-manifold";
            if (topology.non_manifold_edges > 0)
                what += ": " + count_of(topology.non_manifold_edges, "edge", "edges") + " shared by more than two triangles";
            else
                what += ": a vertex joins separate sheets";
            report.problems.push_back(what);
        } else {
            report.problems.push_back("triangles are not consistently oriented");
        }
    }

    // Orientation and self-intersection need a proper polygon mesh; a non-manifold soup leaves them unknown.
    if (!report.manifold) {
        report.outward = false;
        if (options.check_self_intersections) report.self_intersection_free.reset();
    } else {
        if (report.closed && consistently_oriented) {
            if (options.progress) options.progress(0.15);
            std::string problem = orientation_problem(mesh);
            // Each component's volume is taken about its own first vertex; the mesh's, in a frame scaled to
            // its extent, where coordinates 1e-300 of that extent underflow (fuzz_mesh: a tetrahedron with one
            // vertex at 4e274 and three near 0 measured 0). A volume the mesh cannot be measured to is refused.
            if (problem.empty() && !(report.volume > 0))
                problem = "its volume measures " + format_number(report.volume) +
                          " in double precision: its coordinates span too many orders of magnitude";
            report.outward = problem.empty();
            if (!report.outward) report.problems.push_back(problem);
        }
        if (options.check_self_intersections) {
            SurfaceMesh surface;
            build_surface(points, polygons, surface, options.progress);
            std::optional<FacePair> crossing;
            if (options.progress) {
                options.progress(kSelfIntersectionStart);
                std::size_t reads = 0;
                const PollingPointMap points_read(surface, options.progress, kSelfIntersectionStart, reads);
                crossing = first_crossing(surface, CGAL::parameters::vertex_point_map(points_read));
            } else {
                crossing = first_crossing(surface, CGAL::parameters::all_default());
            }
            report.self_intersection_free = !crossing;
            if (crossing) report.problems.push_back("the surface intersects itself near " + place_of(surface, *crossing));
        }
    }

    if (options.exact_volume) {
        const double difference = std::abs(report.volume - *options.exact_volume);
        report.volume_ok = difference <= options.volume_tolerance;
        if (!report.volume_ok)
            report.problems.push_back("volume " + format_number(report.volume) + " differs from the exact " +
                                      format_number(*options.exact_volume) + " by " + format_number(difference) +
                                      ", more than the allowed " + format_number(options.volume_tolerance));
    }
    if (options.progress) options.progress(1.0);
    return report;
}

}  // namespace ratbez::exporter
