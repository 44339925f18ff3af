// ruled.hpp: exact ruled surfaces. Between two coaxial circles the surface is the frustum's lateral surface
// (every point on the cone to 1e-12); between any two curves every isocurve in v is the straight segment
// from a(u) to b(u), and the boundaries are the curves themselves.

#include "ratbez/ruled.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "nurbs_test_support.hpp"
#include "ratbez/curves.hpp"

namespace ratbez {
namespace {

using test::Rng;

TEST(RuledSurface, CoaxialCirclesGiveTheFrustum) {
    const double r1 = 1.0, r2 = 2.5, h = 3.0;
    const NurbsSurface s = ruled_surface(circle(r1, {0, 0, 0}), circle(r2, {0, 0, h}));
    EXPECT_EQ(s.degree_u(), 2);
    EXPECT_EQ(s.degree_v(), 1);
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 10; ++j) {
            const Vec3 p = s.point(i / 40.0, j / 10.0);
            // On the cone: the radius grows linearly with the height.
            EXPECT_NEAR(std::hypot(p.x, p.y), r1 + (r2 - r1) * p.z / h, 1e-12);
            EXPECT_GE(p.z, -1e-15);
            EXPECT_LE(p.z, h + 1e-15);
        }
}

TEST(RuledSurface, StraightRulingsBetweenAnyCurves) {
    // align = false: point u of a is ruled to point u of b, each over its own domain mapped onto [0, 1].
    // b is a random curve of its own degree and knots that follows a (a's points at b's Greville abscissae,
    // moved by up to 0.3) 6 above it, so that most rulings do not cross; the surfaces that meet themselves or
    // pinch (a ruling where S_u and S_v line up) are refused (issue 26), which between two unrelated random
    // curves is most of them, and of these wiggly ones (random knots with C0 joints) still many.
    Rng rng(1804);
    int ruled = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const NurbsCurve a = test::random_curve(rng, trial % 2 == 0, trial % 3 != 0, 4);
        NurbsCurve b = test::random_curve(rng, trial % 4 < 2, true, 4);
        std::vector<Vec4> pw = b.homogeneous_points();
        const int p = b.degree();
        for (std::size_t i = 0; i < pw.size(); ++i) {
            double greville = 0;
            for (int k = 1; k <= p; ++k) greville += b.knots()[i + static_cast<std::size_t>(k)];
            greville = p > 0 ? greville / p : b.knots()[i];
            const Interval bd = b.domain(), ad = a.domain();
            const double f = std::clamp((greville - bd.min) / bd.width(), 0.0, 1.0);
            const Vec3 on_a = a.point(ad.min + f * ad.width());
            pw[i] = homogenize(on_a + Vec3{test::uniform(rng, -0.3, 0.3), test::uniform(rng, -0.3, 0.3), 6}, pw[i].w);
        }
        b = NurbsCurve::from_homogeneous(b.degree(), b.knots(), pw, b.is_rational());
        std::optional<NurbsSurface> surface;
        try {
            surface = ruled_surface(a, b, false);
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("ruled surface"), std::string::npos) << e.what();
            continue;
        }
        ++ruled;
        const NurbsSurface& s = *surface;
        const double size = std::max(a.control_box().diagonal(), b.control_box().diagonal());
        for (int k = 0; k <= 10; ++k) {
            const double f = k / 10.0;
            const Vec3 pa = a.point(a.domain().min + f * a.domain().width());
            const Vec3 pb = b.point(k == 10 ? b.domain().max : b.domain().min + f * b.domain().width());
            ASSERT_LE(distance(s.point(f, 0.0), pa), 1e-11 * size);
            ASSERT_LE(distance(s.point(f, 1.0), pb), 1e-11 * size);
            // Inside: on the segment [pa, pb].
            const Vec3 p = s.point(f, 0.37);
            const Vec3 chord = pb - pa;
            const double t = dot(p - pa, chord) / dot(chord, chord);
            ASSERT_LE(distance(p, pa + chord * t), 1e-10 * size);
            ASSERT_GE(t, -1e-12);
            ASSERT_LE(t, 1 + 1e-12);
        }
    }
    EXPECT_GE(ruled, 8);
}

TEST(RuledSurface, ALineToAnArcRaisesTheDegreeAndMergesKnots) {
    const NurbsSurface s = ruled_surface(line_segment({-1, 0, 0}, {1, 0, 0}), arc(1.0, 180, 360, {0, 0, 1}));
    EXPECT_EQ(s.degree_u(), 2);
    EXPECT_EQ(s.knots_u(), arc(1.0, 180, 360).knots());
    EXPECT_LE(distance(s.point(0.5, 1.0), {0, -1, 1}), 1e-15);
    EXPECT_LE(distance(s.point(0.5, 0.0), {0, 0, 0}), 1e-15);
}

}  // namespace
}  // namespace ratbez
