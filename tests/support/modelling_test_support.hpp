#pragma once
// Paths the sweep tests and benchmarks share (tests/core, tests/occt, tests/openscad, bench/modelling_bench):
// a helix as C1 piecewise cubic Hermite quarter turns, and the length of a curve.

#include <cmath>
#include <numbers>
#include <vector>

#include "ratbez/bspline_basis.hpp"
#include "ratbez/hermite.hpp"
#include "ratbez/join.hpp"
#include "ratbez/nurbs_curve.hpp"

namespace ratbez::test {

// The helix (a cos t, a sin t, c t), t from 0 through quarter_turns quarter turns, each quarter the cubic
// with the helix's end points and end derivatives (hermite_to_bezier), joined into one NurbsCurve (C1).
inline NurbsCurve helix_path(double a, double c, int quarter_turns) {
    const double step = std::numbers::pi / 2;
    auto point = [&](double t) { return Vec3{a * std::cos(t), a * std::sin(t), c * t}; };
    auto tangent = [&](double t) { return Vec3{-a * std::sin(t), a * std::cos(t), c} * step; };
    std::vector<NurbsCurve> parts;
    for (int k = 0; k < quarter_turns; ++k) {
        const double t0 = k * step, t1 = (k + 1) * step;
        parts.push_back(NurbsCurve::from_bezier(hermite_to_bezier(point(t0), tangent(t0), point(t1), tangent(t1))));
    }
    return join(parts);
}

// The length of a curve: 16-point Gauss-Legendre on 64 pieces of every span (to rounding for these
// smooth polynomial pieces).
inline double curve_length(const NurbsCurve& c) {
    static const double x[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                                0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
    static const double w[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                                0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
    const std::vector<double> breaks = breakpoints(c.degree(), c.knots());
    double total = 0;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
        for (int piece = 0; piece < 64; ++piece) {
            const double a = breaks[k] + (breaks[k + 1] - breaks[k]) * piece / 64.0;
            const double b = breaks[k] + (breaks[k + 1] - breaks[k]) * (piece + 1) / 64.0;
            const double m = 0.5 * (a + b), h = 0.5 * (b - a);
            for (int i = 0; i < 8; ++i)
                for (const double s : {-1.0, 1.0}) total += h * w[i] * norm(c.derivative(m + s * h * x[i]));
        }
    return total;
}

}  // namespace ratbez::test
