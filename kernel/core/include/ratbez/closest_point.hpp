#pragma once
// The nearest point of a NURBS curve or surface to a given point (point projection, The NURBS Book §6.1):
// global, not just a local Newton solve ("global seeds, then Newton"). The curve or surface is cut into
// its Bézier spans and each span into weight-certified pieces (rational weights within a factor 4 of
// each other over a piece, so the parameterisation cannot crowd a piece's geometry into a sliver of its
// parameters), each with the box of its control points, which contains it (convex hull property).
// A query visits the pieces nearest box first and stops once no box is nearer than the best point found.
//  - On a curve, a piece along which the distance may have more than one critical point (more than one
//    sign change in the Bernstein coefficients of its derivative: variation diminishing) is halved until
//    none does; the minimum of each piece is then at an end or where Newton's method on
//    (C - P) . C' = 0 (§6.1) leads from the piece's nearest sample. Up to rounding that is the
//    global minimum.
//  - On a surface, Newton's method on (S - P) . S_u = (S - P) . S_v = 0 (Eq. 6.6-6.8), globalised by a line
//    search and kept inside the piece (a parameter on the piece's boundary is held there while the
//    gradient points out; a foot on a side shared with the next piece goes on there), starts from every
//    seed of a grid over the pieces that is no farther than its neighbours; every seed is a candidate
//    too; a start that ends on a side of the domain starts once more half a seed spacing inside (an
//    interior minimum beside the side's). The four sides of the domain (those not collapsed to a pole)
//    are searched as curves, above, so a foot on the boundary is found with the curves' guarantee. That
//    finds the true minimum on ordinary surfaces; an interior basin of the distance narrower than the seed
//    spacing (near the focal points of a strongly curved piece) can still be missed: on random rational
//    bicubic patches 1 point in 50,000 or fewer.

#include <limits>
#include <memory>

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

// The nearest point of a curve: its parameter, the point C(u) and its distance to the point projected.
struct CurveFoot {
    double u = 0;
    Vec3 point;
    double distance = std::numeric_limits<double>::infinity();
};

// The nearest point of a surface: its parameters, the point S(u, v) and its distance to the point projected.
struct SurfaceFoot {
    double u = 0, v = 0;
    Vec3 point;
    double distance = std::numeric_limits<double>::infinity();
};

namespace detail {
struct CurvePieces;   // closest_point.cpp
struct SurfaceCells;  // closest_point.cpp
}  // namespace detail

// Projects many points onto one curve or surface: its pieces, their boxes and (on a surface) the seeds
// are computed once, in the constructor; the shape need not outlive the projector. Copies share them.
template <class Shape, class Foot, class Pieces>
class Projector {
public:
    explicit Projector(const Shape& shape);
    // The nearest point of the shape to p; throws Error naming "point" when p is not finite.
    Foot closest_point(const Vec3& p) const;

private:
    std::shared_ptr<const Pieces> pieces_;
};
using CurveProjector = Projector<NurbsCurve, CurveFoot, detail::CurvePieces>;
using SurfaceProjector = Projector<NurbsSurface, SurfaceFoot, detail::SurfaceCells>;
extern template class Projector<NurbsCurve, CurveFoot, detail::CurvePieces>;
extern template class Projector<NurbsSurface, SurfaceFoot, detail::SurfaceCells>;

// One point: CurveProjector(curve).closest_point(p), SurfaceProjector(surface).closest_point(p).
CurveFoot closest_point(const NurbsCurve& curve, const Vec3& p);
SurfaceFoot closest_point(const NurbsSurface& surface, const Vec3& p);

}  // namespace ratbez
