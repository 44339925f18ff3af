#pragma once
// Shared vertices and edges for the code that builds B-reps (the builders of modelling/, the transforms
// and tables of brep/): one object per vertex and edge, shared by every coedge that uses it. Not
// installed, not part of the public API.

#include <memory>
#include <utility>

#include "ratbez/brep.hpp"

namespace ratbez::detail {

// Vertex of the control points' convex combination: a shared vertex object.
inline VertexPtr make_vertex(const Vec3& p) { return std::make_shared<const Vertex>(Vertex{p}); }
inline EdgePtr make_edge(NurbsCurve curve, VertexPtr start, VertexPtr end, bool degenerate = false) {
    return std::make_shared<const Edge>(Edge{std::move(curve), std::move(start), std::move(end), degenerate});
}

}  // namespace ratbez::detail
