#pragma once
// The quotient rule that turns derivatives of a homogeneous curve or surface (C^w = (A, w), S^w = (A, w))
// into derivatives of its projection, shared by the Bézier and the NURBS classes. Not installed, not part
// of the public API. Inline: both run on the evaluation hot path.

#include <cstddef>
#include <span>
#include <string>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// Pascal's triangle up to row `rows - 1`, flat: table[n * rows + k] = C(n, k) (0 for k > n), by additions
// (exact up to row 56, within rounding beyond). O(rows^2) once: calling binomial() inside the quotient
// rules made them a power slower (a rational Bézier curve's 200th derivative took O(k^3)).
class PascalTriangle {
public:
    explicit PascalTriangle(std::size_t rows) : rows_(rows), table_(rows * rows) {
        for (std::size_t n = 0; n < rows; ++n) {
            table_[n * rows] = 1.0;
            for (std::size_t k = 1; k <= n; ++k)
                table_[n * rows + k] = table_[(n - 1) * rows + k - 1] + (k < n ? table_[(n - 1) * rows + k] : 0.0);
            for (std::size_t k = n + 1; k < rows; ++k) table_[n * rows + k] = 0.0;
        }
    }
    double operator()(std::size_t n, std::size_t k) { return table_[n * rows_ + k]; }

private:
    std::size_t rows_;
    Scratch<double, 36> table_;  // orders up to 5 (the limit normal's) on the stack
};

// A4.2, the quotient rule on A = w C solved for C^(k): from ckw[k] = d^k C^w / du^k, k = 0..ck.size()-1,
// C^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) C^(k-i)) / w. Requires w = ckw[0].w > 0. O(k^2).
inline void rational_curve_derivatives(std::span<const Vec4> ckw, std::span<Vec3> ck) {
    const double w = ckw[0].w;
    PascalTriangle binomial(ck.size());
    for (std::size_t k = 0; k < ck.size(); ++k) {
        Vec3 numerator = weighted_part(ckw[k]);
        for (std::size_t i = 1; i <= k; ++i) numerator -= (binomial(k, i) * ckw[i].w) * ck[k - i];
        ck[k] = numerator / w;
    }
}

// One policy for every evaluator (points, curve and surface derivatives of any order): an answer that is
// not a finite double is an Error naming the parameter, never inf or NaN handed out. With the weights in
// (1/2, 1] (weights_internal.hpp) and the basis functions as ratios of knot differences, a point is finite
// whenever it is representable; a derivative scales like 1 / (knot span)^k and can genuinely overflow.
inline constexpr const char* kBeyondDoubles = " is not a finite number (a knot span or weight ratio too extreme, or "
                                              "coordinates too large, for double precision)";

inline const Vec3& require_finite_point(const Vec3& point, double u) {
    if (!is_finite(point)) [[unlikely]] fail("u", "the point at u = " + number(u) + kBeyondDoubles);
    return point;
}

inline const Vec3& require_finite_point(const Vec3& point, double u, double v) {
    if (!is_finite(point)) [[unlikely]]
        fail("(u, v)", "the point at (" + number(u) + ", " + number(v) + ")" + kBeyondDoubles);
    return point;
}

// derivatives[k] = C^(k)(u).
inline void require_finite_derivatives(std::span<const Vec3> derivatives, double u) {
    for (std::size_t k = 0; k < derivatives.size(); ++k)
        if (!is_finite(derivatives[k])) [[unlikely]]
            fail("u", "the derivative of order " + std::to_string(k) + " at u = " + number(u) + kBeyondDoubles);
}

// skl[k * stride + l] = d^{k+l} S / du^k dv^l for k + l < stride.
inline void require_finite_partials(std::span<const Vec3> skl, std::size_t stride, double u, double v) {
    for (std::size_t k = 0; k < stride; ++k)
        for (std::size_t l = 0; k + l < stride; ++l)
            if (!is_finite(skl[k * stride + l])) [[unlikely]]
                fail("(u, v)", "the derivative of order (" + std::to_string(k) + ", " + std::to_string(l) + ") at (" +
                                   number(u) + ", " + number(v) + ")" + kBeyondDoubles);
}

// A4.4, the quotient rule on A = w S solved for S (the surface form of Eq. 1.28 differentiated), on flat
// arrays aw[k * stride + l] = d^{k+l} S^w / du^k dv^l and skl[k * stride + l] for k + l < stride:
// SKL = (A_kl - sum_{j=1..l} C(l,j) w_0j SKL_{k,l-j} - sum_{i=1..k} C(k,i) w_i0 SKL_{k-i,l}
//        - sum_{i=1..k} C(k,i) sum_{j=1..l} C(l,j) w_ij SKL_{k-i,l-j}) / w_00. Requires w_00 > 0.
inline void rational_surface_derivatives(std::span<const Vec4> aw, std::span<Vec3> skl, std::size_t stride) {
    const double w = aw[0].w;
    PascalTriangle binomial(stride);
    for (std::size_t k = 0; k < stride; ++k) {
        for (std::size_t l = 0; k + l < stride; ++l) {
            Vec3 numerator = weighted_part(aw[k * stride + l]);
            for (std::size_t j = 1; j <= l; ++j) numerator -= (binomial(l, j) * aw[j].w) * skl[k * stride + l - j];
            for (std::size_t i = 1; i <= k; ++i) {
                const double binomial_ki = binomial(k, i);
                numerator -= (binomial_ki * aw[i * stride].w) * skl[(k - i) * stride + l];
                Vec3 mixed;
                for (std::size_t j = 1; j <= l; ++j)
                    mixed += (binomial(l, j) * aw[i * stride + j].w) * skl[(k - i) * stride + l - j];
                numerator -= binomial_ki * mixed;
            }
            skl[k * stride + l] = numerator / w;
        }
    }
}

}  // namespace ratbez::detail
