// Gauss–Legendre rules on [0, 1] (gauss_legendre.hpp): the roots of P_n by Newton's method, weights
// 2 / ((1 - x^2) P_n'(x)^2) on [-1, 1], mapped to [0, 1].
#include "math/gauss_legendre.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "ratbez/error.hpp"

namespace ratbez::detail {

const GaussRule& gauss_legendre(int points) {
    constexpr int max_points = 32;
    static const std::array<GaussRule, max_points + 1> rules = [] {
        std::array<GaussRule, max_points + 1> all{};
        for (int n = 1; n <= max_points; ++n) {
            GaussRule& rule = all[static_cast<std::size_t>(n)];
            // P_n(x) by its three-term recurrence and P_n'(x) = n (x P_n - P_{n-1}) / (x^2 - 1).
            const auto legendre = [n](double x) {
                double p0 = 1.0, p1 = x;
                for (int k = 2; k <= n; ++k) {
                    const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                if (n == 1) p0 = 1.0;
                return std::pair<double, double>{p1, n * (x * p1 - p0) / (x * x - 1.0)};
            };
            for (int i = 0; i < n; ++i) {
                // Newton's method on P_n from the classical initial guess.
                double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
                for (int iteration = 0; iteration < 100; ++iteration) {
                    const auto [value, slope] = legendre(x);
                    const double step = value / slope;
                    x -= step;
                    if (std::abs(step) < 1e-16) break;
                }
                const double derivative = legendre(x).second;
                rule.nodes.push_back((1.0 - x) / 2.0);
                rule.weights.push_back(1.0 / ((1.0 - x * x) * derivative * derivative));  // 2/(...) halved for [0, 1]
            }
        }
        return all;
    }();
    require(points >= 1 && points <= max_points, "points", "Gauss–Legendre rules exist here for 1..32 points");
    return rules[static_cast<std::size_t>(points)];
}

}  // namespace ratbez::detail
