#pragma once
// The convex hull of a mesh's vertices as a closed, outward mesh (from CGAL's 3D Delaunay triangulation, one
// answer for one input), for convex solids:
// a mesh within the tolerance of a convex solid, whose vertices lie at most the tolerance outside it, has a
// hull within the same tolerance both ways (the hull holds the mesh, and lies inside the solid grown by the
// tolerance, which is convex), and the hull is what OpenSCAD's hull() and minkowski() take fast. Vertices
// strictly inside the hull drop out; the rest keep the mesh's order. The exporters hull a convex solid's mesh
// again after rounding its coordinates for the file, which can leave a vertex a little above its neighbours.

#include "ratbez/mesh.hpp"

namespace ratbez {

Mesh convex_hull(const Mesh& mesh);
// Whether a closed mesh is convex: at every edge the far vertex of the neighbouring triangle lies on or below
// the triangle's plane (exact predicates). Meshes that already are need no hull: checked first, in O(edges).
bool is_convex_mesh(const Mesh& mesh);

}  // namespace ratbez
