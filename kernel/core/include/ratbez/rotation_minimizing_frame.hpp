#pragma once
// Rotation-minimising frames (RMF) along a curve by the double reflection method of W. Wang, B. Jüttler,
// D. Zheng and Y. Liu, "Computation of rotation minimizing frames", ACM TOG 27(1), 2008, Algorithm 1.
// A rotation-minimising frame (t, r, s = t x r) turns only as much as the tangent t does: r' = -(t' . r) t,
// no spin about t. The method maps the frame at x_i to x_{i+1} by two reflections: the first in the plane
// bisecting x_i x_{i+1} (taking x_i to x_{i+1}), the second in the plane that then takes the reflected
// tangent onto t_{i+1}. Each step is exact for a circular arc's chord and the global error is O(h^4) in
// the step h; the frame stays orthonormal to rounding however many steps are taken.

#include <vector>

#include "ratbez/vec.hpp"

namespace ratbez {

// One step: the reference vector r_{i+1} at (x_{i+1}, t_{i+1}) from r_i at (x_i, t_i). Tangents are unit,
// r_i is unit and normal to t_i; the result is unit and normal to t_{i+1}. Coincident points skip the first
// reflection, equal tangents the second.
Vec3 double_reflection(const Vec3& x_i, const Vec3& t_i, const Vec3& r_i, const Vec3& x_next, const Vec3& t_next);

// The reference vectors r_0 .. r_n along points x_k with unit tangents t_k, starting from r_0 (unit, normal to
// t_0): r[k] by double_reflection from r[k - 1]. Throws Error naming "tangents" unless there is one tangent
// per point.
std::vector<Vec3> rotation_minimizing_frame(const std::vector<Vec3>& points, const std::vector<Vec3>& tangents,
                                            const Vec3& r0);

}  // namespace ratbez
