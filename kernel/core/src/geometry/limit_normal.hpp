#pragma once
// The limit normal of a surface where S_u x S_v vanishes (a collapsed edge, a pole, the apex of a cone, a
// cusp), shared by BezierSurface::normal and NurbsSurface::normal. Not installed, not part of the public API.

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The Taylor expansion below runs to order 3 in the path parameter, so it needs the partials S_{k,l} of
// total order k + l <= 4, stored as partials[k * limit_normal_stride + l].
inline constexpr int limit_normal_taylor_order = 3;
inline constexpr std::size_t limit_normal_stride = limit_normal_taylor_order + 2;
using LimitNormalPartials = std::array<Vec3, limit_normal_stride * limit_normal_stride>;

// Eq. 1.4 has no value where S_u x S_v = 0, but the tangent plane exists (000 §1.1) and the normal is the
// limit of N along a path (u, v) + t (a, b), t > 0, into the surface. Expand
//   S_u(t) = sum_p t^p U_p,  U_p = (1/p!) sum_r C(p,r) a^r b^(p-r) S_{r+1,p-r},
//   S_v(t) = sum_p t^p V_p,  V_p = (1/p!) sum_r C(p,r) a^r b^(p-r) S_{r,p-r+1};
// then S_u x S_v = sum_q t^q N_q with N_q = sum_p U_p x V_{q-p}, and the limit direction is the first N_q
// that does not vanish (for S_u = 0 along v = v0: N_1 = b S_uv x S_v, the familiar pole formula; b < 0 on
// the opposite edge flips it, as it must). N_q "vanishes" when |N_q| <= 1e-10 times
// max_p M_{p+1} M_{q-p+1} path_scale^q, where M_k = max(floors[k], max_r |S_{r,k-r}|) is the size of the
// partials of total order k, floored so that rounding noise in an exactly vanishing partial is never
// mistaken for a direction. Returns nothing when every N_q, q <= 3, vanishes.
std::optional<Vec3> limit_normal(const LimitNormalPartials& partials, double a, double b,
                                 const std::array<double, limit_normal_stride>& floors, double path_scale);

// The Error for a point without a tangent plane, naming "(u, v)"; u and v are already formatted.
[[noreturn]] void throw_no_tangent_plane(const std::string& u, const std::string& v);

}  // namespace ratbez::detail
