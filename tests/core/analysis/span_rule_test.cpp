// The Gauss–Legendre rule straight on knot spans (kernel/core/src/analysis/span_rule.hpp): it is the same rule as
// on the extracted Bézier patches, exact on polynomial integrands with enough nodes, and a curve is a
// net of one column.

#include "analysis/span_rule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "math/gauss_legendre.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/primitives.hpp"

namespace ratbez::detail {
namespace {

double volume_integrand(const SurfaceFirstDerivatives& d) { return dot(d.s, cross(d.su, d.sv)) / 3.0; }
double area_integrand(const SurfaceFirstDerivatives& d) { return norm(cross(d.su, d.sv)); }

// The n x n rule on each Bézier patch over its own [0, 1]^2 (bezier_patch_first_derivatives: no knots).
double rule_on_patches(const NurbsSurface& surface, int n, const SpanIntegrand& f) {
    const GaussRule& g = gauss_legendre(n);
    double sum = 0;
    for (const auto& row : surface.bezier_patches())
        for (const BezierSurface& patch : row)
            for (std::size_t i = 0; i < g.nodes.size(); ++i)
                for (std::size_t j = 0; j < g.nodes.size(); ++j)
                    sum += g.weights[i] * g.weights[j] *
                           f(bezier_patch_first_derivatives(patch.homogeneous_points().data(), patch.degree_u(),
                                                            patch.degree_v(), g.nodes[i], g.nodes[j]));
    return sum;
}

TEST(SpanRule, IsTheSameRuleAsOnTheBezierPatches) {
    // A torus with unequal interior knots in both directions (knot insertion keeps the geometry), so the
    // spans differ in length and the integrand must be scaled by each span's own length.
    const NurbsSurface torus_surface = torus(3, 1.2, {0, 0, 1}, {0.5, -1, 2})
                                           .faces()[0]
                                           .surface()
                                           .insert_knot_u(0.1)
                                           .insert_knot_v(0.37);
    for (int n : {1, 3, 6}) {
        for (const SpanIntegrand& f : {SpanIntegrand(volume_integrand), SpanIntegrand(area_integrand)}) {
            const double on_spans = span_rule(span_net(torus_surface), n, n, f);
            const double on_patches = rule_on_patches(torus_surface, n, f);
            EXPECT_NEAR(on_spans, on_patches, 1e-12 * std::abs(on_patches)) << n << " nodes";
        }
    }
    // With 6 nodes the rule on the torus' certified arcs is already close to the exact volume 2π² R r².
    const double volume = span_rule(span_net(torus_surface), 6, 6, volume_integrand);
    EXPECT_NEAR(volume, 2 * std::numbers::pi * std::numbers::pi * 3 * 1.2 * 1.2, 1e-3 * volume);
}

TEST(SpanRule, ExactOnPolynomialIntegrandsAcrossUnequalSpans) {
    // S(u, v) = (u, v, u² v) on [0, 1]^2 as a degree (2, 1) Bézier patch, cut at u = 0.3, 0.8 and v = 0.55:
    // S · (S_u x S_v) = -2 u² v, so (1/3) ∫∫ = -1/9; degree 5 in u and 2 in v, exact with 3 x 2 nodes.
    const NurbsSurface graph = NurbsSurface(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1},
                                            {{{0, 0, 0}, {0, 1, 0}}, {{0.5, 0, 0}, {0.5, 1, 0}}, {{1, 0, 0}, {1, 1, 1}}})
                                   .insert_knot_u(0.3)
                                   .insert_knot_u(0.8)
                                   .insert_knot_v(0.55);
    EXPECT_NEAR(span_rule(span_net(graph), 3, 2, volume_integrand), -1.0 / 9.0, 1e-15);
    EXPECT_GT(std::abs(span_rule(span_net(graph), 1, 1, volume_integrand) + 1.0 / 9.0), 1e-3);  // too few nodes
}

TEST(SpanRule, ACurveIsANetOfOneColumn) {
    // Green's area (1/2) ∮ (x y' - y x') of the unit square as one closed degree-1 NURBS curve: exact with
    // one node per span (the integrand is constant on a segment); S_v is zero.
    const NurbsCurve square(1, {0, 0, 1, 2, 3, 4, 4}, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}});
    const auto green = [](const SurfaceFirstDerivatives& d) {
        EXPECT_EQ(norm(d.sv), 0.0);
        return 0.5 * (d.s.x * d.su.y - d.s.y * d.su.x);
    };
    EXPECT_NEAR(span_rule(span_net(square), 1, 1, green), 1.0, 1e-15);
    // A circle is rational: the quick rule is close, not exact.
    EXPECT_NEAR(span_rule(span_net(circle(2.0)), 6, 1, green), 4 * std::numbers::pi, 1e-4);
}

TEST(SpanRule, ControlWeightRatio) {
    // The torus' arcs carry weights 1 and cos 45° in each direction: products from 1/2 to 1.
    EXPECT_NEAR(control_weight_ratio(torus(3, 1).faces()[0].surface().homogeneous_points()), 2.0, 1e-15);
    EXPECT_EQ(control_weight_ratio(line_segment({0, 0, 0}, {1, 2, 3}).homogeneous_points()), 1.0);
}

}  // namespace
}  // namespace ratbez::detail
