// curvature.hpp: curve curvature against closed forms and 000's Ex1.3 (a cusp where C' = 0, an inflection
// where C' || C''), and principal curvatures of the exact primitives (sphere, cylinder, torus), poles included.

#include "ratbez/curvature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "ratbez/curves.hpp"
#include "ratbez/power_basis.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/revolve.hpp"
#include "test_support.hpp"

namespace ratbez {
namespace {

constexpr double pi = std::numbers::pi;

// The cubic of the power basis coefficients a_0..a_3 (000 Ex1.3) as a Bézier curve on [0, 1] (Ex. 1.14).
NurbsCurve power_cubic(const std::vector<Vec3>& a) { return NurbsCurve::from_bezier(BezierCurve(power_to_bezier(a))); }

TEST(CurveCurvature, CircleArcsAndEllipse) {
    const NurbsCurve c = circle(2.5, {1, 2, 3}, {1, 1, 0});
    for (int k = 0; k <= 40; ++k) EXPECT_NEAR(curvature(c, k / 40.0), 1 / 2.5, 1e-13);
    // Ellipse x = a cos t, y = b sin t: kappa = a b / (a^2 sin^2 t + b^2 cos^2 t)^(3/2), at t = 0: a / b^2.
    const NurbsCurve e = ellipse_arc(3.0, 1.0, 0, 180);
    EXPECT_NEAR(curvature(e, 0.0), 3.0, 1e-12);
    EXPECT_NEAR(curvature(e, 0.5), 1.0 / 9.0, 1e-12);  // t = 90 degrees: b / a^2
    EXPECT_EQ(curvature(line_segment({0, 0, 0}, {1, 2, 3}), 0.3), 0.0);
    EXPECT_ERROR_NAMING(curvature(c, 1.5), "u");
}

TEST(CurveCurvature, Ex13CuspAndInflection) {
    // A cusp: C(u) = (4 (u - 1/2)^2, 8 (u - 1/2)^3) has C'(1/2) = 0 and C'' not parallel to C''': kappa -> inf.
    const NurbsCurve cusp = power_cubic({{1, -1, 0}, {-4, 6, 0}, {4, -12, 0}, {0, 8, 0}});
    EXPECT_EQ(curvature(cusp, 0.5), std::numeric_limits<double>::infinity());
    EXPECT_TRUE(std::isfinite(curvature(cusp, 0.25)));
    // An inflection: C(u) = (u, (u - 1/2)^3): C'' = 0 at u = 1/2, kappa = 0 there and > 0 beside it.
    const NurbsCurve inflection = power_cubic({{0, -0.125, 0}, {1, 0.75, 0}, {0, -1.5, 0}, {0, 1, 0}});
    EXPECT_EQ(curvature(inflection, 0.5), 0.0);
    // kappa = |y''| / (1 + y'^2)^(3/2) with y' = 3 (u - 1/2)^2, y'' = 6 (u - 1/2).
    const double u = 0.8, y1 = 3 * 0.09, y2 = 6 * 0.3;
    EXPECT_NEAR(curvature(inflection, u), y2 / std::pow(1 + y1 * y1, 1.5), 1e-13);
    // A stationary point on a straight line, C(u) = ((u - 1/2)^3, 0): no bending, kappa = 0.
    const NurbsCurve stop = power_cubic({{-0.125, 0, 0}, {0.75, 0, 0}, {-1.5, 0, 0}, {1, 0, 0}});
    EXPECT_EQ(curvature(stop, 0.5), 0.0);
}

TEST(CurveCurvature, ZeroSpeedOfASmoothParabolaGivesItsLimit) {
    // C(s) = (s^2, s^4) with s = u - 1/2 traces y = x^2 (x >= 0) with C' = 0 at s = 0: k = 2, l = 4 = 2k,
    // a = 1, b = |C''''| / 4! = 1, so kappa -> 2 b / a^2 = 2, the parabola's curvature at its vertex.
    const double h = 0.5;
    // Power coefficients in u of ((u - h)^2, (u - h)^4); degree 4, Bézier by Ex. 1.14.
    const std::vector<Vec3> a{{h * h, h * h * h * h, 0}, {-2 * h, -4 * h * h * h, 0}, {1, 6 * h * h, 0}, {0, -4 * h, 0}, {0, 1, 0}};
    const NurbsCurve c = NurbsCurve::from_bezier(BezierCurve(power_to_bezier(a)));
    EXPECT_NEAR(curvature(c, 0.5), 2.0, 1e-9);
}

TEST(SurfaceCurvatures, SphereCylinderTorus) {
    const double r = 1.5;
    const NurbsSurface s = sphere(r, {1, 1, 1}).faces()[0].surface();
    for (const auto& [u, v] : std::vector<std::pair<double, double>>{{0.3, 0.4}, {0.9, 0.77}, {0.5, 0.5}}) {
        const PrincipalCurvatures k = principal_curvatures(s, u, v);
        EXPECT_NEAR(k.k1, -1 / r, 1e-12);  // the outward normal: the sphere bends away from it
        EXPECT_NEAR(k.k2, -1 / r, 1e-12);
        EXPECT_NEAR(dot(k.dir1, k.normal), 0, 1e-12);
        EXPECT_NEAR(dot(k.dir1, k.dir2), 0, 1e-12);
    }
    // The poles: the parameterisation degenerates, the limit remains.
    for (const double v : {s.domain_v().min, s.domain_v().max}) {
        const PrincipalCurvatures pole = principal_curvatures(s, 0.3, v);
        EXPECT_NEAR(pole.k1, -1 / r, 1e-8 / r);
        EXPECT_NEAR(pole.k2, -1 / r, 1e-8 / r);
    }
    // An oblate spheroid (a half ellipse, semi-axes a = 2 across and b = 1 along the axis, revolved): at the
    // poles both curvatures are the ellipse's b / a^2 there, and they vary on the way (the limit is not
    // just a nearby value).
    const NurbsSurface spheroid = revolve(Profile({ellipse_arc(2.0, 1.0, -90, 90, {0, 0, 0}, {0, -1, 0})})).faces()[0].surface();
    for (const double v : {spheroid.domain_v().min, spheroid.domain_v().max}) {
        const PrincipalCurvatures pole = principal_curvatures(spheroid, 0.7, v);
        EXPECT_NEAR(pole.k1, -0.25, 0.25e-8);
        EXPECT_NEAR(pole.k2, -0.25, 0.25e-8);
        EXPECT_NEAR(std::abs(pole.normal.z), 1, 1e-15);
    }
    // At the equator: along the meridian a / b^2 = 2, around the axis 1 / a.
    const PrincipalCurvatures equator = principal_curvatures(spheroid, 0.7, 0.5);
    EXPECT_NEAR(equator.k1, -0.5, 1e-12);
    EXPECT_NEAR(equator.k2, -2.0, 1e-12);
    const Solid cyl = cylinder(2.0, 3.0);
    const PrincipalCurvatures c = principal_curvatures(cyl.faces()[0].surface(), 0.3, 0.5);
    EXPECT_NEAR(c.k1, 0, 1e-12);
    EXPECT_NEAR(c.k2, -0.5, 1e-12);
    EXPECT_NEAR(std::abs(c.dir1.z), 1, 1e-12);  // straight along the axis
    // Torus R = 3, r = 1: along the tube -1/r; around the axis cos(theta) / (R + r cos(theta)), theta the tube
    // angle from the outer equator. The tube circle starts at the outer equator (v = 0: theta = 0).
    const NurbsSurface t = torus(3.0, 1.0).faces()[0].surface();
    for (const double v : {0.0, 0.125, 0.25, 0.5}) {
        const double theta = 2 * pi * v;  // the tube is a full circle over v in [0, 1] at arc layout angles
        const Vec3 p = t.point(0.2, v);
        const double rho = std::hypot(p.x, p.y);
        const double cos_theta = (rho - 3.0) / 1.0;
        const PrincipalCurvatures k = principal_curvatures(t, 0.2, v);
        const double around = -cos_theta / rho;  // outward normal
        EXPECT_NEAR(std::max(k.k1, k.k2), std::max(-1.0, around), 1e-12) << "theta " << theta;
        EXPECT_NEAR(std::min(k.k1, k.k2), std::min(-1.0, around), 1e-12);
    }
}

}  // namespace
}  // namespace ratbez
