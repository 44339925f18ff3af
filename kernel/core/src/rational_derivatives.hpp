#pragma once
// The quotient rule that turns derivatives of a homogeneous curve or surface (C^w = (A, w), S^w = (A, w))
// into derivatives of its projection, shared by the Bézier and the NURBS classes. Not installed, not part
// of the public API. Inline: both run on the evaluation hot path.

#include <cstddef>
#include <span>

#include "numeric_internal.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// A4.2, the quotient rule on A = w C solved for C^(k): from ckw[k] = d^k C^w / du^k, k = 0..ck.size()-1,
// C^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) C^(k-i)) / w. Requires w = ckw[0].w > 0.
inline void rational_curve_derivatives(std::span<const Vec4> ckw, std::span<Vec3> ck) {
    const double w = ckw[0].w;
    for (std::size_t k = 0; k < ck.size(); ++k) {
        Vec3 numerator = weighted_part(ckw[k]);
        for (std::size_t i = 1; i <= k; ++i)
            numerator -= (binomial(static_cast<int>(k), static_cast<int>(i)) * ckw[i].w) * ck[k - i];
        ck[k] = numerator / w;
    }
}

// A4.4, the quotient rule on A = w S solved for S (the surface form of Eq. 1.28 differentiated), on flat
// arrays aw[k * stride + l] = d^{k+l} S^w / du^k dv^l and skl[k * stride + l] for k + l < stride:
// SKL = (A_kl - sum_{j=1..l} C(l,j) w_0j SKL_{k,l-j} - sum_{i=1..k} C(k,i) w_i0 SKL_{k-i,l}
//        - sum_{i=1..k} C(k,i) sum_{j=1..l} C(l,j) w_ij SKL_{k-i,l-j}) / w_00. Requires w_00 > 0.
inline void rational_surface_derivatives(std::span<const Vec4> aw, std::span<Vec3> skl, std::size_t stride) {
    const double w = aw[0].w;
    for (std::size_t k = 0; k < stride; ++k) {
        for (std::size_t l = 0; k + l < stride; ++l) {
            Vec3 numerator = weighted_part(aw[k * stride + l]);
            for (std::size_t j = 1; j <= l; ++j)
                numerator -= (binomial(static_cast<int>(l), static_cast<int>(j)) * aw[j].w) * skl[k * stride + l - j];
            for (std::size_t i = 1; i <= k; ++i) {
                const double binomial_ki = binomial(static_cast<int>(k), static_cast<int>(i));
                numerator -= (binomial_ki * aw[i * stride].w) * skl[(k - i) * stride + l];
                Vec3 mixed;
                for (std::size_t j = 1; j <= l; ++j)
                    mixed += (binomial(static_cast<int>(l), static_cast<int>(j)) * aw[i * stride + j].w) *
                             skl[(k - i) * stride + l - j];
                numerator -= binomial_ki * mixed;
            }
            skl[k * stride + l] = numerator / w;
        }
    }
}

}  // namespace ratbez::detail
