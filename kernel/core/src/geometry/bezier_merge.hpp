#pragma once
// Two Bézier pieces that meet end to start, as ONE Bézier of the same degree when they are two parts of one:
// what the section alignment uses to drop a breakpoint where every section runs on smoothly (a circle's own
// arc joint opposite the middle of a square's side), so that a loft or ruled surface keeps no knot there and
// OpenCASCADE no face edge. Defined in bezier_merge.cpp. Not installed, not part of the public API.
//
// Two kinds are recognised, each by construction and then checked on the pieces' own points:
//  - straight pieces of any degree, rational or not: every control point on the segment from the first
//    piece's start to the second's end, in order along it (a rational piece with positive weights then
//    traces the segment once, by the variation diminishing property); merged into the segment with evenly
//    spaced control points, weights 1;
//  - conic arcs (degree 2, positive weights): the merged arc runs from the first start P0 to the second end
//    P2, its middle control point P1 where the end tangents meet (the tangent property of 000 §1.4), and its
//    middle weight w (end weights 1, the normal form) puts the joint J on it. With J = a P0 + b P1 + c P2
//    (barycentric, a + b + c = 1), the rational quadratic's point at t has a : b : c = (1 - t)^2 :
//    2 w t (1 - t) : t^2 (Eq. 1.14 with w0 = w2 = 1), so t = sqrt c / (sqrt a + sqrt c) and
//    w = (1 - t)^2 b / (2 t (1 - t) a). Ex1.13's quarter circle cut at 1/2 (Ex1.14) gives back its polygon.
// The merged piece is accepted only when points at 4 inner parameters of each piece lie on it (each point's
// own t by the same barycentric rule) within `tolerance`, in order, and its middle weight is at least 1/2 (a
// circle's arc of up to 120 degrees; at a half turn w reaches 0 and the middle point infinity).

#include <optional>
#include <vector>

#include "ratbez/vec.hpp"

namespace ratbez::detail {

// `first` and `second`: homogeneous control points (w > 0) of equal degree, first's last point the same as
// second's first after projection. The merged piece's homogeneous points, end weights 1; nullopt when the
// pieces are not parts of one straight segment or one conic arc (of middle weight >= 1/2) to `tolerance`
// (absolute, model units).
std::optional<std::vector<Vec4>> merged_bezier(const std::vector<Vec4>& first, const std::vector<Vec4>& second,
                                               double tolerance);

}  // namespace ratbez::detail
