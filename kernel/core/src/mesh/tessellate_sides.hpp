#pragma once
// The four sides of a surface face as the tessellator sees them: which edge each lies on, how the
// face's parameter along the side maps to the edge's own parameter, and the merged parameter lists an
// edge is sampled at (the union of the lines of the faces that share it). Not installed, not part of
// the public API.

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "ratbez/brep.hpp"

namespace ratbez::detail {

// The sides in the order of Face::sides(): bottom, right, top, left of the (u, v) domain.
inline constexpr std::array<Side, 4> kSides{Side::v_min, Side::u_max, Side::v_max, Side::u_min};
// A side's position in Face::sides() and in every per-side array of the tessellator.
inline std::size_t side_slot(Side s) { return static_cast<std::size_t>(s); }
// True for the sides along which u runs (v fixed): v_min and v_max.
inline bool runs_along_u(Side s) { return s == Side::v_min || s == Side::v_max; }
// The parameter a side holds fixed: v = v_min on Side::v_min, u = u_max on Side::u_max, ...
double side_parameter(const NurbsSurface& surface, Side side);

struct SideMap {
    const Edge* edge = nullptr;
    bool degenerate = false;
    bool flipped = false;  // the edge runs against the face parameter (tolerated, brep.hpp says it does not)
    double p0 = 0, p1 = 1;  // the face's parameter range along the side
    double t0 = 0, t1 = 1;  // the edge's domain

    // Both maps stay inside the range they map into: the affine formula rounds, and a parameter one ulp past
    // an end is outside the curve's domain.
    double to_edge(double p) const {
        if (p == p0) return flipped ? t1 : t0;
        if (p == p1) return flipped ? t0 : t1;
        const double s = (p - p0) / (p1 - p0);
        return std::clamp(flipped ? t1 - s * (t1 - t0) : t0 + s * (t1 - t0), std::min(t0, t1), std::max(t0, t1));
    }
    double to_face(double t) const {
        if (t == t0) return flipped ? p1 : p0;
        if (t == t1) return flipped ? p0 : p1;
        const double s = (t - t0) / (t1 - t0);
        return std::clamp(flipped ? p1 - s * (p1 - p0) : p0 + s * (p1 - p0), std::min(p0, p1), std::max(p0, p1));
    }
};

// The map of one side of a surface face; throws Error naming "solid" when the side has no edge.
SideMap map_side(const Face& face, Side side);

// Sorted, with values closer than a relative 1e-12 of [t0, t1] merged and values outside dropped; both
// ends present and exact.
std::vector<double> merge_params(std::vector<double> params, double t0, double t1);

}  // namespace ratbez::detail
