#include "ratbez/profile.hpp"

#include <string>

#include "geometry/clamping.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {

namespace {
// Relative joint tolerance: far above the rounding of any exact construction (~1e-16), far below any
// gap a user would draw on purpose.
constexpr double kRelativeJointTolerance = 1e-9;

// A rational span whose end weights differ by more than this factor crowds its parameter into one end:
// along one span of round-trip seed 20264282 (weights 2.4e-3 .. 71) the speed fell from 0.64 to 2e-10,
// OCCT's wire check took two parameters 1e-8 apart on the cap's pcurve for a self-intersection, and every
// sampling of the parameter (tessellation, deviation, cubature) spends its samples where nothing happens.
// Such pieces are put in normal form; milder weights keep the user's parameterisation and continuity.
constexpr double kMaxEndWeightRatio = 4;

bool has_uneven_span(const NurbsCurve& piece) {
    if (!piece.is_rational()) return false;
    for (const BezierCurve& span : piece.bezier_segments()) {
        const double first = span.homogeneous_points().front().w, last = span.homogeneous_points().back().w;
        if (first > kMaxEndWeightRatio * last || last > kMaxEndWeightRatio * first) return true;
    }
    return false;
}
}  // namespace

Profile::Profile(std::vector<NurbsCurve> pieces) {
    require(!pieces.empty(), "profile", "must have at least one piece");
    std::size_t total = 0;
    for (const NurbsCurve& piece : pieces) total += piece.homogeneous_points().size();
    limits::require_curve_points(total, "profile");  // before the per-piece work below grows with it
    Box box;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        require(pieces[k].degree() >= 1, "profile",
                [&] { return "piece " + std::to_string(k) + " has degree 0 (a point)"; });
        pieces[k] = detail::clamped(pieces[k]);
        if (has_uneven_span(pieces[k])) pieces[k] = pieces[k].normal_form();
        const Box piece_box = pieces[k].control_box();
        require(piece_box.diagonal() > 0, "profile",
                [&] { return "piece " + std::to_string(k) + " is a single point"; });
        box.add(piece_box);
    }
    size_ = box.diagonal();
    tolerance_ = kRelativeJointTolerance * size_;

    for (std::size_t k = 1; k < pieces.size(); ++k) {
        const Vec3 previous_end = pieces[k - 1].end_point();
        const double gap = distance(previous_end, pieces[k].start_point());
        require(gap <= tolerance_, "profile", [&] {
            return "piece " + std::to_string(k) + " starts at " + detail::format_point(pieces[k].start_point()) + ", " +
                   std::to_string(gap) + " away from the end " + detail::format_point(previous_end) + " of piece " +
                   std::to_string(k - 1) + " (pieces must meet)";
        });
        pieces[k] = detail::with_end_point(pieces[k], false, previous_end);
    }
    closed_ = distance(pieces.back().end_point(), pieces.front().start_point()) <= tolerance_;
    if (closed_) pieces.back() = detail::with_end_point(pieces.back(), true, pieces.front().start_point());
    pieces_ = std::move(pieces);
}

Profile Profile::from_beziers(const std::vector<BezierCurve>& pieces) {
    std::vector<NurbsCurve> nurbs;
    nurbs.reserve(pieces.size());
    for (const BezierCurve& piece : pieces) nurbs.push_back(NurbsCurve::from_bezier(piece));
    return Profile(std::move(nurbs));
}

Vec3 Profile::start_point() const { return pieces_.front().start_point(); }
Vec3 Profile::end_point() const { return pieces_.back().end_point(); }

Profile Profile::reversed() const {
    std::vector<NurbsCurve> pieces;
    pieces.reserve(pieces_.size());
    for (auto it = pieces_.rbegin(); it != pieces_.rend(); ++it) pieces.push_back(it->reversed());
    return Profile(std::move(pieces));
}

}  // namespace ratbez
