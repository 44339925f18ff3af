// The limit normal by the Taylor expansion of S_u x S_v along a path (Eq. 1.4 at its singular points);
// see limit_normal.hpp.

#include "geometry/limit_normal.hpp"

#include <algorithm>
#include <cmath>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"

namespace ratbez::detail {

std::optional<Vec3> limit_normal(const LimitNormalPartials& partials, double a, double b,
                                 const std::array<double, limit_normal_stride>& floors, double path_scale) {
    constexpr std::size_t stride = limit_normal_stride;
    const auto skl = [&](std::size_t k, std::size_t l) -> const Vec3& { return partials[k * stride + l]; };

    // magnitude[k]: the largest partial of total order k, floored by the caller's rounding scale.
    std::array<double, stride> magnitude{};
    for (std::size_t k = 1; k < stride; ++k) {
        magnitude[k] = floors[k];
        for (std::size_t r = 0; r <= k; ++r) magnitude[k] = std::max(magnitude[k], norm(skl(r, k - r)));
    }

    std::array<Vec3, limit_normal_taylor_order + 1> u_terms, v_terms;
    double factorial = 1.0;
    for (std::size_t p = 0; p < u_terms.size(); ++p) {
        if (p > 0) factorial *= static_cast<double>(p);
        Vec3 up, vp;
        for (std::size_t r = 0; r <= p; ++r) {
            const double coefficient = binomial(static_cast<int>(p), static_cast<int>(r)) *
                                       std::pow(a, static_cast<double>(r)) * std::pow(b, static_cast<double>(p - r));
            up += coefficient * skl(r + 1, p - r);
            vp += coefficient * skl(r, p - r + 1);
        }
        u_terms[p] = up / factorial;
        v_terms[p] = vp / factorial;
    }

    constexpr double relative_tolerance = 1e-10;
    for (std::size_t q = 0; q < u_terms.size(); ++q) {
        Vec3 n;
        double scale = 0.0;
        for (std::size_t p = 0; p <= q; ++p) {
            n += cross(u_terms[p], v_terms[q - p]);
            scale = std::max(scale, magnitude[p + 1] * magnitude[q - p + 1] *
                                        std::pow(path_scale, static_cast<double>(q)));
        }
        const double length = norm(n);
        if (length > relative_tolerance * scale && length > 0.0) return n / length;
    }
    return std::nullopt;
}

void throw_no_tangent_plane(const std::string& u, const std::string& v) {
    throw Error("(u, v)", "the surface has no tangent plane at (" + u + ", " + v +
                "); its partial derivatives are parallel or zero to order " +
                std::to_string(limit_normal_taylor_order + 1));
}

}  // namespace ratbez::detail
