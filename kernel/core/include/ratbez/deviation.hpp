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

// The largest distance from a point of the mesh to the solid's boundary surface.
double max_deviation(const Solid& solid, const Mesh& mesh, const DeviationOptions& options = {});

}  // namespace ratbez
