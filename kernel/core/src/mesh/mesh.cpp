#include "ratbez/mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

#include "ratbez/error.hpp"
#include "ratbez/mesh_topology.hpp"

namespace ratbez {
namespace {

// volume() and area() read the vertices a triangle names: an index past the table is an Error, not a
// read out of bounds (meshes come from files and users too, not only from tessellate).
void require_valid_indices(const Mesh& mesh) {
    const std::size_t count = mesh.vertices.size();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (const std::uint32_t index : mesh.triangles[t])
            if (index >= count)  // not require(): the message is built only on failure
                throw Error("mesh", "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(index) +
                            " but there are only " + std::to_string(count) + " vertices");
}

}  // namespace

bool Mesh::is_closed() const {
    // Each directed edge appears exactly once and its reverse exactly once (mesh_topology.hpp).
    for (const auto& t : triangles)
        for (const std::uint32_t v : t)
            if (v >= vertices.size()) return false;
    if (triangles.empty()) return false;
    const MeshTopology topology = mesh_topology(*this);
    return topology.closed() && topology.repeated_edges == 0 && topology.degenerate_triangles == 0;
}

double Mesh::volume() const {
    require_valid_indices(*this);
    double six_volume = 0;
    for (const auto& t : triangles)
        six_volume += dot(vertices[t[0]], cross(vertices[t[1]], vertices[t[2]]));
    return six_volume / 6.0;
}

double Mesh::area() const {
    require_valid_indices(*this);
    double twice_area = 0;
    for (const auto& t : triangles)
        twice_area += norm(cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]));
    return twice_area / 2.0;
}

}  // namespace ratbez
