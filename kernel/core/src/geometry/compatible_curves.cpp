// Knot-vector merging (A5.4 by repeated A5.1) after degree elevation (degree_elevation.hpp): see
// compatible_curves.hpp.
#include "ratbez/compatible_curves.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/clamping.hpp"
#include "ratbez/degree_elevation.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"

namespace ratbez {

namespace {

using detail::to_size;

// Knots of different curves closer than this (on the common domain [0, 1]) are one knot.
constexpr double kKnotMergeDistance = 1e-12;

}  // namespace

std::vector<NurbsCurve> make_compatible(const std::vector<NurbsCurve>& curves, const std::string& argument) {
    require(!curves.empty(), argument, "must contain at least one curve");
    int degree = 0;
    for (const NurbsCurve& c : curves) degree = std::max(degree, c.degree());

    // Same degree and domain [0, 1], clamped (so that the ends are control points).
    std::vector<NurbsCurve> result;
    result.reserve(curves.size());
    for (const NurbsCurve& c : curves)
        result.push_back(elevate_degree(detail::clamped_ends(c), degree - c.degree()).reparameterized(0.0, 1.0));

    // The union of the knot vectors, each knot with its largest multiplicity; near-equal knots merged.
    struct Knot {
        double value;
        int multiplicity;
    };
    std::vector<Knot> merged;  // interior knots only, ascending
    auto interior_knots = [](const NurbsCurve& c) {
        std::vector<Knot> knots;
        for (const double u : c.knots()) {
            if (u <= 0.0 || u >= 1.0) continue;
            if (!knots.empty() && knots.back().value == u)
                ++knots.back().multiplicity;
            else
                knots.push_back({u, 1});
        }
        return knots;
    };
    for (NurbsCurve& c : result) {
        std::vector<Knot> own = interior_knots(c);
        bool moved = false;
        for (Knot& k : own) {
            const auto near = std::find_if(merged.begin(), merged.end(),
                                           [&](const Knot& m) { return std::abs(m.value - k.value) <= kKnotMergeDistance; });
            if (near == merged.end()) {
                merged.push_back(k);
                continue;
            }
            if (near->value != k.value) {
                k.value = near->value;
                moved = true;
            }
            near->multiplicity = std::max(near->multiplicity, k.multiplicity);
        }
        std::sort(merged.begin(), merged.end(), [](const Knot& x, const Knot& y) { return x.value < y.value; });
        if (moved) {
            // Rewrite the curve's knots onto the merged values (a shift below 1e-12 of the domain).
            std::vector<double> knots(to_size(degree + 1), 0.0);
            for (const Knot& k : own) knots.insert(knots.end(), to_size(k.multiplicity), k.value);
            knots.insert(knots.end(), to_size(degree + 1), 1.0);
            c = NurbsCurve::from_homogeneous(degree, std::move(knots), c.homogeneous_points(), c.is_rational());
        }
    }
    for (NurbsCurve& c : result) {
        const std::vector<Knot> own = interior_knots(c);
        for (const Knot& k : merged) {
            const auto it = std::find_if(own.begin(), own.end(), [&](const Knot& o) { return o.value == k.value; });
            const int have = it == own.end() ? 0 : it->multiplicity;
            if (k.multiplicity > have) c = c.insert_knot(k.value, k.multiplicity - have);
        }
    }
    return result;
}

}  // namespace ratbez
