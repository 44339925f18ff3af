#pragma once
// Measuring how far a mesh strays from the exact solid: every triangle is sampled densely and each
// sample is projected onto the nearest face (point inversion: a coarse grid seed, then Newton on
// (S(u,v) - P) . S_u = (S(u,v) - P) . S_v = 0). Works for any mesh of the solid, ours or another
// mesher's (BRepMesh, OpenSCAD's sphere), which is what makes the comparison fair.

#include "ratbez/brep.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/progress.hpp"

namespace ratbez {

struct DeviationOptions {
    int samples_per_edge = 6;  // barycentric samples per triangle: (n+1)(n+2)/2, vertices included
    Progress progress;         // optional: called with the share of triangles measured; may throw to cancel
};

// The largest distance from a point of the mesh to the solid's boundary surface. The samples include the
// vertices, so a mesh whose vertices lie off the surface (one that straddles it, tessellate.hpp) is
// measured at its outermost points too.
double max_deviation(const Solid& solid, const Mesh& mesh, const DeviationOptions& options = {});

// The other direction: the largest distance from a point of the solid's boundary to the mesh, i.e. how
// well the mesh covers the surface (a mesh close to the surface can still leave part of it out: a gap, a
// fin it cuts across). Every surface face is sampled on a parameter grid at about the spacing of
// max_deviation's samples on the mesh (per weight-certified piece of every knot span, as many parts as
// the piece is long), every planar face on its boundary polyline and on rows across its region, and each
// sample's distance to the nearest triangle found through a uniform grid of the triangles. With
// max_deviation it gives the two-sided (Hausdorff) distance; infinity for a mesh without triangles.
double max_surface_to_mesh_distance(const Solid& solid, const Mesh& mesh, const DeviationOptions& options = {});

}  // namespace ratbez
