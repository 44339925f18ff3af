#pragma once
// CGAL checks that every mesh we hand out is a valid solid boundary: closed, 2-manifold, consistently
// outward oriented, free of self-intersections, and with a volume close to the exact one.

#include <optional>
#include <string>
#include <vector>

#include "ratbez/mesh.hpp"

namespace ratbez::exporter {

struct MeshCheckOptions {
    bool check_self_intersections = true;  // the expensive test; a flag skips it for very large meshes
    std::optional<double> exact_volume;    // when given, the mesh volume must lie within volume_tolerance
    double volume_tolerance = 0;           // absolute
};

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
