#pragma once
// Extreme rational weights brought into (1/2, 1] by a power of two, for every rational curve and surface
// class. The projection H (Eq. 1.16) is invariant under a common factor of the homogeneous points, so the
// curve or surface is unchanged; with every weight at most 1 the homogeneous points w P and the sums of
// A1.4, A3.1 and A4.3 stay within the size of the control points (weights of 1e308 gave C(0.5) = inf where
// the answer is an ordinary point). Ordinary weights, in [2^-64, 2^64] with every w P finite, are kept as
// given, so the homogeneous points are the textbook's P^w = (w P, w) (Table 1.4). A power of two scales
// exactly, so the user's weights are given back exactly (2^-k w). Not installed, not part of the public API.

#include <algorithm>
#include <cmath>
#include <iterator>
#include <span>

#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The exponent k with largest * 2^k in (1/2, 1]; 0 when it is there already (weights of 1 stay 1).
inline int weight_scale_exponent(double largest) {
    int exponent = 0;
    const double mantissa = std::frexp(largest, &exponent);  // largest = mantissa * 2^exponent, mantissa in [1/2, 1)
    return mantissa == 0.5 ? 1 - exponent : -exponent;
}

// The scale exponent of positive finite weights (validated by the caller): 0 for ordinary weights whose
// products w P are all finite (`products_finite`), else the one of weight_scale_exponent, reduced where it
// would push the smallest weight below the normal double range (weights from 1e-300 to 1e300 are a valid
// curve: scaled as far as the smallest allows; an evaluation that still leaves the double range is then an
// Error of the evaluator, never inf or NaN).
template <class Weights>
int weight_scale_exponent_of(const Weights& weights, bool products_finite = true) {
    double largest = 0, smallest = 0;
    bool first = true;
    for (const double w : weights) {
        largest = first ? w : std::max(largest, w);
        smallest = first ? w : std::min(smallest, w);
        first = false;
    }
    if (first || (products_finite && largest <= 0x1p64 && largest >= 0x1p-64)) return 0;
    int smallest_exponent = 0;
    std::frexp(smallest, &smallest_exponent);  // smallest >= 2^(smallest_exponent - 1)
    return std::max(weight_scale_exponent(largest), -1020 - smallest_exponent);
}

// Whether w_i P_i is finite for every control point and weight.
template <class Points, class Weights>
bool products_finite(const Points& points, const Weights& weights) {
    auto w = std::begin(weights);
    for (const Vec3& p : points) {
        if (!is_finite(p * *w)) return false;
        ++w;
    }
    return true;
}

// Every homogeneous point times 2^exponent (exact: the weights stay normal numbers).
inline void scale_homogeneous(std::span<Vec4> points, int exponent) {
    if (exponent == 0) return;
    for (Vec4& p : points) p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent),
                                std::ldexp(p.w, exponent)};
}

}  // namespace ratbez::detail
