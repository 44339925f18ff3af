// Hermite <-> Bézier for cubics (003); see hermite.hpp.
#include "ratbez/hermite.hpp"

#include "ratbez/error.hpp"

namespace ratbez {

BezierCurve hermite_to_bezier(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1) {
    require(is_finite(p0), "p0", "must have finite coordinates");
    require(is_finite(t0), "t0", "must have finite coordinates");
    require(is_finite(p1), "p1", "must have finite coordinates");
    require(is_finite(t1), "t1", "must have finite coordinates");
    return BezierCurve({p0, p0 + t0 / 3.0, p1 - t1 / 3.0, p1});
}

HermiteForm bezier_to_hermite(const BezierCurve& curve) {
    require(!curve.is_rational(), "curve", "is rational; a cubic Hermite form describes polynomial curves only");
    require(curve.degree() <= 3, "curve", [&] {
        return "has degree " + std::to_string(curve.degree()) + "; a cubic Hermite form holds degree 3 at most";
    });
    BezierCurve cubic = curve;
    while (cubic.degree() < 3) cubic = cubic.elevate();
    const std::vector<Vec3> b = cubic.points();
    return HermiteForm{b[0], (b[1] - b[0]) * 3.0, b[3], (b[3] - b[2]) * 3.0};
}

}  // namespace ratbez
