#pragma once
// The weight rule of tessellation: rational weights within one Bézier piece of a face at most
// kMaxTessellationWeightRatio apart. Beyond it weights crowd a surface into slivers of its parameters that
// the tensor grid of tessellate_plan.hpp follows only with a huge or failing mesh, measured on revolved
// profiles at tolerance 0.01 of size 1 (the ratio is the profile's times the circle's sqrt(2)): a cubic with
// weights 1, W, W, 1 meshed in 2,000 triangles at W = 100, 111,000 at 1e6, 2.2M at 1e8 and needed over 20M
// at 1e10; a quadratic 1, W, 1 meshed up to W = 1e10 but failed "(u, v): the surface has no tangent plane"
// at 1e12, as did a ring of two such pieces at 1e10 and every piece at 1e300, after building (issue 29).
// Refused up front instead, naming the ratio. The randomized round trips (weights within 10^+-3 per control
// point, joined and revolved) reach 1.4e7. Not installed, not part of the public API.

#include <span>

#include "ratbez/brep.hpp"

namespace ratbez::detail {

inline constexpr double kMaxTessellationWeightRatio = 1e9;

// The largest max w / min w over the control points of any one knot span pair of `surface` (the weights
// of the Bézier patch there are convex combinations of those, so they lie within it).
double largest_span_weight_ratio(const NurbsSurface& surface);

// Error naming `argument` when a surface face's largest_span_weight_ratio exceeds kMaxTessellationWeightRatio.
void require_tessellatable_weights(std::span<const Face> faces, const char* argument);

}  // namespace ratbez::detail
