#pragma once
// The combinatorics of a triangle mesh, before any geometry: how its edges are shared and whether the
// triangles around each vertex form one fan. What Mesh::is_closed and the export's CGAL checks
// (openscad_export) read: CGAL's polygon_soup_to_polygon_mesh requires an oriented 2-manifold soup.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "ratbez/mesh.hpp"
#include "ratbez/progress.hpp"

namespace ratbez {

struct MeshTopology {
    std::size_t degenerate_triangles = 0;  // naming one vertex twice; left out of the counts below
    std::size_t border_edges = 0;          // undirected edges used by one triangle
    std::size_t non_manifold_edges = 0;    // undirected edges used by more than two triangles
    std::size_t repeated_edges = 0;        // directed edges used by more than one triangle: neighbours whose
                                           // orientations disagree (or a non-manifold edge)
    std::size_t singular_vertices = 0;     // vertices whose triangles form more than one fan: sheets that
                                           // touch at a point
    // One edge {a, b} (a < b) that keeps the mesh from being watertight (a border, non-manifold or repeated edge), the
    // first by its smaller vertex: where an error can point the user. None when there is no such edge.
    std::optional<std::array<std::uint32_t, 2>> defective_edge;

    // Every edge used by exactly two triangles.
    bool closed() const { return border_edges == 0 && non_manifold_edges == 0; }
    // Closed, every edge used once each way and no triangle naming a vertex twice (Mesh::is_closed).
    bool watertight() const { return closed() && repeated_edges == 0 && degenerate_triangles == 0; }
    // A consistently oriented 2-manifold, with or without boundary.
    bool oriented_manifold() const {
        return degenerate_triangles == 0 && non_manifold_edges == 0 && repeated_edges == 0 && singular_vertices == 0;
    }
};

// In time linear in the mesh for bounded valence (n log n at worst): the triangles are gathered per vertex
// (compressed rows) and each vertex's star is sorted and scanned alone. `progress` (optional) gets the
// share of vertices done every 65,536 vertices; it may throw to cancel (progress.hpp).
// Error naming "mesh" when a triangle names a vertex past the table.
MeshTopology mesh_topology(const Mesh& mesh, const Progress& progress = {});

}  // namespace ratbez
