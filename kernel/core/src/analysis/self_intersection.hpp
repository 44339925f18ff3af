#pragma once
// Whether a surface meets itself: a certified test, for the surfaces of ruled solids, lofts and sweeps (a
// twisted hourglass, a profile swept round a bend tighter than itself, sections that cross). Either it
// proves that the surface is one-to-one (up to its seams: a closed strip's u = end is its u = start, a
// collapsed side is one point), or it finds two distinct places that meet. Defined in
// self_intersection.cpp. Not installed, not part of the public API.
//
// The certificate (per parameter rectangle R, the surface possibly rational and made of several Bézier
// patches): if there are directions d+ and d- with
//     d+ . S_u > 0,  d+ . S_v > 0,  d- . S_u > 0,  d- . S_v < 0   everywhere on R,
// then S is one-to-one on R. Proof: for p != q in R with h = p - q, S(p) - S(q) = integral over the segment
// from q to p of h_u S_u + h_v S_v; when h_u and h_v have the same sign its dot product with d+ has that sign
// and is not zero, when opposite signs its dot product with d-; so S(p) != S(q). (Creases in R are fine: the
// conditions are on S_u and S_v wherever they exist; a collapsed side of the strip, where S_v or S_u
// vanishes identically, may have a zero coefficient on it: the only pairs it cannot separate lie on that
// side, which is one point.) The signs are certified, not sampled: d . S_u has the sign of
// d . (w A_u - w_u A) (S^w = (A, w), the quotient rule without its positive denominator w^2), a polynomial
// whose Bernstein coefficients on each patch restricted to R (de Casteljau) are formed by the Bernstein
// product rule; all of them of the right sign prove the sign everywhere (convex hull property). d+ and d-
// are the sum and the difference of the mean unit u and v tangents over R's patches' corners.
//
// The search: parameter rectangles of a quadtree over the Bézier patches (whole patches first, then halves
// of patches), each with the box of its control points, which contains it. A rectangle is done when the
// certificate holds on it; otherwise its halves are searched and every pair of them. A pair is done when
// their boxes are disjoint, or, when they touch in parameters (across a seam too), when the certificate holds
// on the rectangle spanning both; otherwise the larger is halved. Two rectangles that do not touch but whose
// boxes overlap are first tried for a crossing by Gauss–Newton on S(p) - S(q) = 0 (p, q kept in their own
// rectangles); a solution to 1e-10 of the size is a meeting found. A rectangle or pair that reaches boxes
// smaller than `resolution` without a certificate is a meeting (or a fold) too: the surface comes that close
// to itself. A rectangle within one patch whose certificate fails is first searched for a point without a
// tangent plane (S_u x S_v = 0, by Gauss–Newton): a pinch or fold, which the surface cannot have either.

#include <cstddef>
#include <vector>

#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// Surfaces side by side along u: piece k's u_max side is piece k + 1's u_min side (and, when closed_u, the
// last one's is the first one's); all over the same number of knot spans in v, their v_min and v_max sides
// one another's when closed_v.
struct SurfaceStrip {
    std::vector<NurbsSurface> pieces;
    bool closed_u = false, closed_v = false;
};

struct SelfIntersection {
    bool found = false;      // the surface meets itself (or could not be certified within the budget)
    bool fold = false;       // locally: no tangent plane, the surface turns back on itself
    bool undecided = false;  // the budget of rectangles ran out before a certificate
    Vec3 point;              // where
    std::size_t piece = 0;   // the places that meet, in their pieces' own parameters
    double u = 0, v = 0;
    std::size_t other_piece = 0;
    double other_u = 0, other_v = 0;
    double gap = 0;          // the distance between the two places found
};

// `resolution` (> 0, absolute): boxes smaller than this that still overlap without a certificate count as a
// meeting. `budget`: at most this many rectangles and pairs examined.
SelfIntersection find_self_intersection(const SurfaceStrip& strip, double resolution, std::size_t budget = 30'000);

}  // namespace ratbez::detail
