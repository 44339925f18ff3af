#pragma once
// What a revolution builds before it becomes a Solid: shared by revolve.cpp (which defines it) and the
// primitives made by revolving a profile (sphere, torus). Not installed, not part of the public API.

#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The result of revolving profile pieces (joined end to end, already snapped) about an axis:
// one face per piece, the joint edges (circles or arcs; degenerate on the axis), and the profile edges
// at angle 0 and at the end angle (the same edges for a full turn). joint vertices index 0..m.
struct RevolutionShell {
    std::vector<Face> faces;
    std::vector<EdgePtr> joint_edges;          // m + 1 entries (closed profile: the last is the first)
    std::vector<EdgePtr> start_profile_edges;  // m entries
    std::vector<EdgePtr> end_profile_edges;    // m entries
    std::vector<VertexPtr> start_vertices;     // m + 1 entries
    std::vector<VertexPtr> end_vertices;       // m + 1 entries
};
RevolutionShell build_revolution(const std::vector<NurbsCurve>& pieces, bool closed, const Vec3& axis_point,
                                 const Vec3& unit_axis, double angle_deg);

}  // namespace ratbez::detail
