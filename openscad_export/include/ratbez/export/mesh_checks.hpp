#pragma once
// CGAL checks that every mesh we hand out is a valid solid boundary: closed, 2-manifold, consistently
// outward oriented, free of self-intersections, and with a volume close to the exact one.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "ratbez/mesh.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::exporter {

struct MeshCheckOptions {
    bool check_self_intersections = true;  // the expensive test; a flag skips it for very large meshes
    std::optional<double> exact_volume;    // when given, the mesh volume must lie within volume_tolerance
    double volume_tolerance = 0;           // absolute
    // The checks hold about bytes_per_checked_triangle for each triangle (CGAL's surface mesh, the AABB tree
    // of the self-intersection test); a larger mesh is refused up front with an Error naming "mesh" rather
    // than running out of memory after a minute (8.1M triangles died at a 4 GB cap).
    std::size_t max_triangles = 4'000'000;
    // Optional: called between the checks and, inside the self-intersection test (most of the time), every
    // few thousand point reads with the same fraction; may throw to cancel (progress.hpp).
    Progress progress;
};
inline constexpr std::size_t bytes_per_checked_triangle = 450;

// What the process may still allocate under its address-space and data-segment limits (RLIMIT_AS and
// RLIMIT_DATA, as `ulimit -v`, `prlimit --as` or Python's resource.setrlimit set them), less what it holds
// already (/proc/self/status); nullopt when neither limit is set.
std::optional<std::size_t> memory_left();

// The most triangles the checks take: options.max_triangles, or fewer when memory_left() holds fewer at
// bytes_per_checked_triangle each (450 bytes also covers the tessellation and the mesh written: an export of
// 890k triangles peaked at 290 bytes per triangle). `limit` words it for messages ("the export's mesh
// checks' limit of 4000000 triangles (about 1.8 GB at 450 bytes each)").
struct TriangleLimit {
    std::size_t triangles = 0;
    std::string limit;
};
TriangleLimit checked_triangle_limit(const MeshCheckOptions& options = {});

struct MeshReport {
    bool closed = false;
    bool manifold = false;
    bool outward = false;
    std::optional<bool> self_intersection_free;  // unset when skipped
    bool volume_ok = true;
    double volume = 0;
    std::vector<std::string> problems;  // one line each, empty when ok()
    bool ok() const { return problems.empty(); }
};

MeshReport check_mesh(const Mesh& mesh, const MeshCheckOptions& options = {});

}  // namespace ratbez::exporter
