// The weight rule of tessellation (weight_limit.hpp).
#include "mesh/weight_limit.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"

namespace ratbez::detail {

double largest_span_weight_ratio(const NurbsSurface& surface) {
    if (!surface.is_rational()) return 1;
    const int p = surface.degree_u(), q = surface.degree_v();
    const std::vector<double>& ku = surface.knots_u();
    const std::vector<double>& kv = surface.knots_v();
    double worst = 1;
    // Span i (ku[i] < ku[i + 1], p <= i < rows) is shaped by rows i - p .. i, span j by columns j - q .. j.
    for (int i = p; i < surface.rows(); ++i) {
        if (!(ku[static_cast<std::size_t>(i)] < ku[static_cast<std::size_t>(i) + 1])) continue;
        for (int j = q; j < surface.columns(); ++j) {
            if (!(kv[static_cast<std::size_t>(j)] < kv[static_cast<std::size_t>(j) + 1])) continue;
            double lightest = std::numeric_limits<double>::infinity(), heaviest = 0;
            for (int a = i - p; a <= i; ++a)
                for (int b = j - q; b <= j; ++b) {
                    const double w = surface.homogeneous_point(a, b).w;  // scaled by a power of two: ratios exact
                    lightest = std::min(lightest, w);
                    heaviest = std::max(heaviest, w);
                }
            worst = std::max(worst, heaviest / lightest);
        }
    }
    return worst;
}

static_assert(kMaxTessellationWeightRatio == 1e9, "the message below states the limit as 1e9");

void require_tessellatable_weights(std::span<const Face> faces, const char* argument) {
    for (std::size_t k = 0; k < faces.size(); ++k) {
        if (faces[k].kind() != Face::Kind::surface) continue;
        const double ratio = largest_span_weight_ratio(faces[k].surface());
        require(ratio <= kMaxTessellationWeightRatio, argument, [&] {
            return "face " + std::to_string(k) + " has rational weights " + number(ratio) +
                   " times apart within one Bézier piece, above the limit 1e9" +
                   " that tessellation supports (weights that far apart crowd the surface into slivers of its "
                   "parameters; its volume and area are still measured exactly)";
        });
    }
}

}  // namespace ratbez::detail
