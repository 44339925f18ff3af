// Refusing surfaces that meet themselves; see embedding_check.hpp.
#include "modelling/embedding_check.hpp"

#include "math/numeric_internal.hpp"
#include "ratbez/box.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"

namespace ratbez::detail {

namespace {

// All the control points of a row (fixed u index) or column (fixed v index) of a net in one place.
bool collapsed(const NurbsSurface& s, bool row, int index, double tolerance) {
    const int count = row ? s.columns() : s.rows();
    const Vec3 first = project(row ? s.homogeneous_point(index, 0) : s.homogeneous_point(0, index));
    for (int k = 1; k < count; ++k)
        if (distance(project(row ? s.homogeneous_point(index, k) : s.homogeneous_point(k, index)), first) > tolerance) return false;
    return true;
}

}  // namespace

bool has_collapsed_side(const SurfaceStrip& strip) {
    Box box;
    for (const NurbsSurface& s : strip.pieces) box.add(s.control_box());
    const double tolerance = 1e-12 * box.diagonal();
    if (!strip.closed_u && (collapsed(strip.pieces.front(), true, 0, tolerance) ||
                            collapsed(strip.pieces.back(), true, strip.pieces.back().rows() - 1, tolerance)))
        return true;
    if (!strip.closed_v)
        for (const NurbsSurface& s : strip.pieces)
            if (collapsed(s, false, 0, tolerance) || collapsed(s, false, s.columns() - 1, tolerance)) return true;
    return false;
}

void require_embedded(const SurfaceStrip& strip, const std::string& argument, const std::string& what,
                      const std::function<std::string(const SelfIntersection&)>& where, const std::string& advice) {
    if (has_collapsed_side(strip)) return;
    Box box;
    for (const NurbsSurface& s : strip.pieces) box.add(s.control_box());
    // The search's work grows with the patches (a loft of 2,000 sections: 8,000, each a rectangle and some
    // pairs with its neighbours): a budget per patch, so that a long valid strip is certified, not refused
    // as undecided, and a hostile one still costs bounded work.
    std::size_t patches = 0;
    for (const NurbsSurface& s : strip.pieces)
        patches += (breakpoints(s.degree_u(), s.knots_u()).size() - 1) * (breakpoints(s.degree_v(), s.knots_v()).size() - 1);
    const SelfIntersection found = find_self_intersection(strip, 1e-7 * box.diagonal(), 30'000 + 64 * patches);
    if (!found.found) return;
    if (found.undecided)
        fail(argument, "could not certify that the " + what + " does not meet itself (too intricate to decide); " + advice);
    const std::string how = found.fold ? " folds back on itself (no tangent plane)" : " meets itself";
    fail(argument, "the " + what + how + " near " + format_point(found.point) + where(found) + "; " + advice);
}

}  // namespace ratbez::detail
