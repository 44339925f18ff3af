// Hermite <-> Bézier for cubics (003); see hermite.hpp.
#include "ratbez/hermite.hpp"

#include "ratbez/error.hpp"

namespace ratbez {

BezierCurve hermite_to_bezier(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1) {
    require(is_finite(p0), "p0", "must have finite coordinates");
    require(is_finite(t0), "t0", "must have finite coordinates");
    require(is_finite(p1), "p1", "must have finite coordinates");
    require(is_finite(t1), "t1", "must have finite coordinates");
    // Near the double limit the inner control points can overflow (1e308 + 1e308 / 3): said for the tangent
    // that does it, not for the curve's points, which the caller never passed.
    const Vec3 b1 = p0 + t0 / 3.0, b2 = p1 - t1 / 3.0;
    require(is_finite(b1), "t0", "puts the control point p0 + t0 / 3 beyond the double range");
    require(is_finite(b2), "t1", "puts the control point p1 - t1 / 3 beyond the double range");
    return BezierCurve({p0, b1, b2, p1});
}

HermiteForm bezier_to_hermite(const BezierCurve& curve) {
    require(!curve.is_rational(), "curve", "is rational; a cubic Hermite form describes polynomial curves only");
    require(curve.degree() <= 3, "curve", [&] {
        return "has degree " + std::to_string(curve.degree()) + "; a cubic Hermite form holds degree 3 at most";
    });
    BezierCurve cubic = curve;
    while (cubic.degree() < 3) cubic = cubic.elevate();
    const std::vector<Vec3> b = cubic.points();
    // The end tangents 3 (b1 - b0) and 3 (b3 - b2) of a cubic whose points are near the double limit (a
    // segment from -1e308 to 1e308) are beyond it: an Error, not inf (issue 29).
    const HermiteForm form{b[0], (b[1] - b[0]) * 3.0, b[3], (b[3] - b[2]) * 3.0};
    require(is_finite(form.t0) && is_finite(form.t1), "curve",
            "its end tangents 3 (P1 - P0) and 3 (P3 - P2) are beyond the double range (its control points are too far apart)");
    return form;
}

}  // namespace ratbez
