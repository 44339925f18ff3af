// Bézier subdivision check that a planar profile does not cross itself (see profile_crossings.hpp).

#include "modelling/profile_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "geometry/subdivision.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"

namespace ratbez::detail {
namespace {

constexpr std::size_t kNoCell = std::numeric_limits<std::size_t>::max();
// The smallest feature examined, in units of the tolerance (1e-9 of the profile's size): a loop, or two
// sides of a turn, within 1e-6 of the size of each other along the curve are below what the check resolves.
constexpr double kResolution = 1000;
// Halvings of a span into cells: each halving at an end of the span divides the spread of its end weight
// from the next one by about 2, so weights 1e-300 .. 1e300 need about 2000.
constexpr int kMaxCellDepth = 4096;

// A part [t0, t1] of cell `cell` in plane coordinates: homogeneous control points (x w, y w, w), their
// Euclidean points (x, y, 0) and the box of those.
struct Arc {
    std::vector<Vec3> homogeneous;
    std::vector<Vec3> points;
    Vec3 low, high;
    std::size_t cell = 0;
    double t0 = 0, t1 = 1;

    const Vec3& start() const { return points.front(); }
    const Vec3& end() const { return points.back(); }
    double diagonal() const { return norm(high - low); }
};

// The plane point (x, y, 0) of a homogeneous (x w, y w, w).
Vec3 euclidean(const Vec3& homogeneous) { return {homogeneous.x / homogeneous.z, homogeneous.y / homogeneous.z, 0.0}; }

// The arc of `homogeneous` with Euclidean end points `start` and `end` given: consecutive arcs must share
// their joint bit for bit, which projecting each one's own homogeneous end point does not guarantee (the
// pieces on either side of a joint weight it differently).
Arc make_arc(std::vector<Vec3> homogeneous, const Vec3& start, const Vec3& end, std::size_t cell, double t0, double t1) {
    Arc arc{std::move(homogeneous), {}, {}, {}, cell, t0, t1};
    arc.points.reserve(arc.homogeneous.size());
    for (const Vec3& h : arc.homogeneous) arc.points.push_back(euclidean(h));
    arc.points.front() = start;
    arc.points.back() = end;
    arc.low = arc.high = start;
    for (const Vec3& p : arc.points) {
        arc.low = {std::min(arc.low.x, p.x), std::min(arc.low.y, p.y), 0.0};
        arc.high = {std::max(arc.high.x, p.x), std::max(arc.high.y, p.y), 0.0};
    }
    return arc;
}

std::pair<Arc, Arc> halve(const Arc& arc) {
    auto [left, right] = halve_bezier(arc.homogeneous);
    const Vec3 middle = euclidean(right.front());
    const double t = 0.5 * (arc.t0 + arc.t1);
    return {make_arc(std::move(left), arc.start(), middle, arc.cell, arc.t0, t),
            make_arc(std::move(right), middle, arc.end(), arc.cell, t, arc.t1)};
}

Vec3 turned_left(const Vec3& v) { return {-v.y, v.x, 0.0}; }

bool boxes_apart(const Arc& a, const Arc& b, double tol) {
    return a.low.x > b.high.x + tol || b.low.x > a.high.x + tol || a.low.y > b.high.y + tol || b.low.y > a.high.y + tol;
}

// The fat line of `a`: the strip parallel to its chord holding all its control points. Apart when the
// control points of `b` all lie more than tol beyond one side of it.
bool strip_apart(const Arc& a, const Arc& b, double tol) {
    const Vec3 chord = a.end() - a.start();
    const double length = norm(chord);
    if (!(length > 0)) return false;
    const Vec3 normal = turned_left(chord) / length;
    const auto offsets = [&](const Arc& arc) {
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (const Vec3& p : arc.points) {
            const double d = dot(p - a.start(), normal);
            low = std::min(low, d);
            high = std::max(high, d);
        }
        return std::pair{low, high};
    };
    const auto [a_low, a_high] = offsets(a);
    const auto [b_low, b_high] = offsets(b);
    return b_low > a_high + tol || b_high < a_low - tol;
}

bool apart(const Arc& a, const Arc& b, double tol) {
    return boxes_apart(a, b, tol) || strip_apart(a, b, tol) || strip_apart(b, a, tol);
}

// Control points strictly increasing along the chord: the derivative, a positive combination of the
// P_j - P_i with j > i, then has a positive component along the chord, so the arc cannot meet itself.
bool advances_along_chord(const Arc& arc) {
    const Vec3 chord = arc.end() - arc.start();
    for (std::size_t i = 0; i + 1 < arc.points.size(); ++i)
        if (!(dot(arc.points[i + 1] - arc.points[i], chord) > 0)) return false;
    return true;
}

// `first` ends where `second` starts, at J. They meet nowhere else when a line through J leaves every
// other control point of `first` strictly on one side and of `second` strictly on the other: their hulls
// then share only J. Candidate lines: the one that bisects the angle between the arcs' directions out of
// J, and the one along the direction in which `second` leaves J.
bool meet_only_at_joint(const Arc& first, const Arc& second) {
    const Vec3 joint = second.start();
    // The direction from J to the control point nearest to J along the polygon that is not J itself.
    const auto direction_out_of_joint = [&](auto begin, auto end) -> Vec3 {
        for (auto p = begin; p != end; ++p)
            if (*p != joint) return (*p - joint) / norm(*p - joint);
        return {};
    };
    const Vec3 back = direction_out_of_joint(first.points.rbegin(), first.points.rend());
    const Vec3 ahead = direction_out_of_joint(second.points.begin(), second.points.end());
    if (back == Vec3{} || ahead == Vec3{}) return true;  // an arc that is the single point J
    const auto separates = [&](const Vec3& v) {
        for (const Vec3& p : first.points)
            if (p != joint && !(dot(p - joint, v) < 0)) return false;
        for (const Vec3& p : second.points)
            if (p != joint && !(dot(p - joint, v) > 0)) return false;
        return true;
    };
    return separates(ahead - back) || separates(turned_left(ahead)) || separates(-1.0 * turned_left(ahead));
}

class CrossingCheck {
public:
    // loops[0] is the profile (open or closed), further loops are closed holes (extrude); all in one plane.
    CrossingCheck(std::span<const Profile> loops, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis)
        : origin_(origin), x_axis_(x_axis), y_axis_(y_axis), several_loops_(loops.size() > 1) {
        for (const Profile& loop : loops) tol_ = std::max(tol_, loop.tolerance());
        resolution_ = kResolution * tol_;
        for (std::size_t l = 0; l < loops.size(); ++l) add_loop(loops[l], l);
        budget_ = 1'000'000 + 64 * cells_.size();
    }

    void run() {
        for (const Arc& cell : cells_) check_self(cell);
        // Sweep the cells in order of their boxes' left sides: only boxes that overlap in x can meet.
        std::vector<const Arc*> order;
        for (const Arc& cell : cells_) order.push_back(&cell);
        std::sort(order.begin(), order.end(), [](const Arc* a, const Arc* b) { return a->low.x < b->low.x; });
        for (std::size_t i = 0; i < order.size(); ++i)
            for (std::size_t j = i + 1; j < order.size() && order[j]->low.x <= order[i]->high.x + tol_; ++j) {
                spend();
                if (!boxes_apart(*order[i], *order[j], tol_)) check_pair(*order[i], *order[j]);
            }
    }

private:
    // The cells of one loop, in order. Every joint once: each cell starts where the one before ends (a
    // closed loop's first where its last ends). A run of cells of one piece that are each below tol and
    // together below the resolution (the crawl of a weight such as 1e300 leaves thousands of them on one
    // point) is checked as the straight arc between its ends: what it hides is below the resolution.
    void add_loop(const Profile& profile, std::size_t loop) {
        std::vector<std::vector<Vec3>> rows;
        std::vector<std::size_t> row_pieces;
        for (std::size_t k = 0; k < profile.pieces().size(); ++k)
            for (const BezierCurve& span : profile.pieces()[k].bezier_segments()) {
                std::vector<Vec3> homogeneous;
                for (const Vec4& pw : span.homogeneous_points()) {
                    const Vec3 p = project(pw) - origin_;
                    homogeneous.push_back(Vec3{dot(p, x_axis_), dot(p, y_axis_), 1.0} * pw.w);
                }
                add_cells(homogeneous, k, rows, row_pieces);
            }
        loops_.push_back(Loop{cells_.size(), cells_.size(), profile.is_closed()});
        Vec3 joint = euclidean(profile.is_closed() ? rows.back().back() : rows.front().front());
        for (std::size_t i = 0; i < rows.size();) {
            const std::size_t piece = row_pieces[i];
            Vec3 end = euclidean(rows[i].back());
            Arc cell = make_arc(std::move(rows[i]), joint, end, cells_.size(), 0.0, 1.0);
            std::size_t next = i + 1;
            if (cell.diagonal() <= tol_) {
                Vec3 low = cell.low, high = cell.high;
                for (; next < rows.size() && row_pieces[next] == piece; ++next) {
                    const Vec3 next_end = euclidean(rows[next].back());
                    const Arc following = make_arc(rows[next], end, next_end, 0, 0.0, 1.0);
                    const Vec3 run_low{std::min(low.x, following.low.x), std::min(low.y, following.low.y), 0.0};
                    const Vec3 run_high{std::max(high.x, following.high.x), std::max(high.y, following.high.y), 0.0};
                    if (following.diagonal() > tol_ || norm(run_high - run_low) > resolution_) break;
                    low = run_low;
                    high = run_high;
                    end = next_end;
                }
                cell = make_arc({{joint.x, joint.y, 1.0}, {end.x, end.y, 1.0}}, joint, end, cells_.size(), 0.0, 1.0);
            }
            add_cell(std::move(cell), piece, loop);
            joint = end;
            i = next;
        }
        loops_.back().end = cells_.size();
    }

    // The cells of one span, in order: its pieces of the weight certificate (for_each_certified_piece).
    // Within a cell the parameter moves at a speed bounded relative to the cell's size, so halving a cell
    // halves its geometry roughly too; in a raw span with weights 1e-3 .. 1e3 most of the parameter can
    // crawl within 1e-9 of one point, and parameter halving would chase it with millions of arcs below
    // the tolerance.
    void add_cells(const std::vector<Vec3>& row, std::size_t piece, std::vector<std::vector<Vec3>>& rows,
                   std::vector<std::size_t>& row_pieces) {
        for_each_certified_piece(std::vector<std::vector<Vec3>>{row}, [](const Vec3& h) { return h.z; }, kMaxCellDepth,
                                 [&](const std::vector<std::vector<Vec3>>& lines, double, double) {
                                     rows.push_back(lines.front());
                                     row_pieces.push_back(piece);
                                 });
    }

    void add_cell(Arc cell, std::size_t piece, std::size_t loop) {
        std::vector<Vec4> plane_points;
        for (const Vec3& h : cell.homogeneous) plane_points.push_back({h.x, h.y, 0.0, h.z});
        plane_cells_.push_back(BezierCurve::from_homogeneous(std::move(plane_points)));
        cells_.push_back(std::move(cell));
        piece_of_.push_back(piece);
        loop_of_.push_back(loop);
    }

    // The cell after s along its loop (a closed loop's first after its last), or kNoCell.
    std::size_t next_cell(std::size_t s) const {
        const Loop& loop = loops_[loop_of_[s]];
        if (s + 1 < loop.end) return s + 1;
        return loop.closed ? loop.begin : kNoCell;
    }
    // `a` runs into `b`: b starts at the parameter where a ends, on the same cell or the next one.
    bool runs_into(const Arc& a, const Arc& b) const {
        return (a.cell == b.cell && a.t1 == b.t0) || (a.t1 == 1.0 && b.t0 == 0.0 && next_cell(a.cell) == b.cell);
    }

    // The length of cell s's control polygon over [t0, t1]: an upper bound of the curve's length there.
    double polygon_length(std::size_t s, double t0, double t1) const {
        // t0 / t1 rounds to 1 only for an interval below 1e-16 of the cell's parameter: nothing to measure.
        if (!(t0 < t1) || !(t0 / t1 < 1)) return 0;
        BezierCurve part = plane_cells_[s];
        if (t1 < 1) part = part.split(t1).first;
        if (t0 > 0) part = part.split(t0 / t1).second;
        const std::vector<Vec3> points = part.points();
        double length = 0;
        for (std::size_t i = 0; i + 1 < points.size(); ++i) length += distance(points[i], points[i + 1]);
        return length;
    }

    // Two arcs are neighbours along the profile when the curve between them is no longer than the
    // resolution: in a turn tighter than that (a rational span with weights 1e-3 .. 1e3 can turn within
    // 1e-12 of its size) the two sides lie within tol of each other without the profile crossing itself.
    bool neighbours(const Arc& a, const Arc& b) const {
        return std::min(length_between(a, b), length_between(b, a)) <= resolution_;
    }

    // An upper bound of the length of the curve from the end of `a` forward to the start of `b`, or
    // infinity once it exceeds the resolution (or `b` does not follow `a` at all).
    double length_between(const Arc& a, const Arc& b) const {
        if (a.cell == b.cell && a.t1 <= b.t0) return polygon_length(a.cell, a.t1, b.t0);
        double length = polygon_length(a.cell, a.t1, 1.0);
        std::size_t c = next_cell(a.cell);
        for (std::size_t steps = 0; c != kNoCell && steps < cells_.size() && length <= resolution_; ++steps) {
            if (c == b.cell) return length + polygon_length(c, 0.0, b.t0);
            length += polygon_length(c, 0.0, 1.0);
            c = next_cell(c);
        }
        return std::numeric_limits<double>::infinity();
    }

    void spend() {
        if (++steps_ > budget_)
            fail("profile", "is too intricate to certify within " + std::to_string(budget_) +
                                " subdivision steps that it does not cross itself");
    }

    Vec3 in_space(const Vec3& p) const { return origin_ + x_axis_ * p.x + y_axis_ * p.y; }

    // A cell cannot meet itself once it advances along its chord; else its halves must not meet each other.
    void check_self(const Arc& whole) {
        std::vector<Arc> pending{whole};
        while (!pending.empty()) {
            const Arc arc = std::move(pending.back());
            pending.pop_back();
            spend();
            if (advances_along_chord(arc) || arc.diagonal() <= resolution_) continue;
            auto [left, right] = halve(arc);
            check_pair(left, right);
            pending.push_back(std::move(left));
            pending.push_back(std::move(right));
        }
    }

    void check_pair(const Arc& a0, const Arc& b0) {
        std::vector<std::pair<Arc, Arc>> pending{{a0, b0}};
        while (!pending.empty()) {
            auto [a, b] = std::move(pending.back());
            pending.pop_back();
            spend();
            if (apart(a, b, tol_)) continue;
            if ((runs_into(a, b) && meet_only_at_joint(a, b)) || (runs_into(b, a) && meet_only_at_joint(b, a))) continue;
            if (a.diagonal() <= resolution_ && b.diagonal() <= resolution_ && neighbours(a, b)) continue;
            if (a.diagonal() <= tol_ && b.diagonal() <= tol_) report(a, b);
            // Halve the larger arc: both shrink in turn, and a joined pair keeps exactly one joined child.
            Arc& larger = a.diagonal() >= b.diagonal() ? a : b;
            const Arc& other = &larger == &a ? b : a;
            auto [left, right] = halve(larger);
            pending.emplace_back(std::move(left), other);
            pending.emplace_back(std::move(right), other);
        }
    }

    // Two arcs below tol that could not be told apart: the profile comes within tol of itself there (at a
    // joint, when its two sides leave it in the same direction: a cusp or a fold).
    [[noreturn]] void report(const Arc& a, const Arc& b) const {
        const std::size_t pa = piece_of_[a.cell], pb = piece_of_[b.cell];
        const std::size_t la = loop_of_[a.cell], lb = loop_of_[b.cell];
        const std::string where = format_point(in_space(0.5 * (a.start() + b.start())));
        if (!several_loops_ || (la == 0 && lb == 0)) {
            if (pa == pb) fail("profile", "piece " + std::to_string(pa) + " crosses or touches itself near " + where);
            fail("profile", "pieces " + std::to_string(std::min(pa, pb)) + " and " + std::to_string(std::max(pa, pb)) +
                                " cross or touch near " + where + " (a profile must not cross itself)");
        }
        const auto name = [](std::size_t loop, std::size_t piece) {
            return "piece " + std::to_string(piece) + (loop == 0 ? " of the profile" : " of hole " + std::to_string(loop - 1));
        };
        if (la == lb && pa == pb) fail("holes", name(la, pa) + " crosses or touches itself near " + where);
        fail("holes", name(std::min(la, lb), la <= lb ? pa : pb) + " and " + name(std::max(la, lb), la <= lb ? pb : pa) +
                          " cross or touch near " + where +
                          " (holes must lie inside the profile, apart from it and from each other)");
    }

    // A loop's cells are cells_[begin, end).
    struct Loop {
        std::size_t begin, end;
        bool closed;
    };

    Vec3 origin_, x_axis_, y_axis_;
    double tol_ = 0, resolution_ = 0;
    bool several_loops_;
    std::vector<Loop> loops_;
    std::vector<Arc> cells_;
    std::vector<BezierCurve> plane_cells_;  // the same cells, (x, y, 0) in the plane, for lengths between arcs
    std::vector<std::size_t> piece_of_, loop_of_;
    std::size_t steps_ = 0, budget_ = 0;
};

}  // namespace

void require_no_crossings(const Profile& profile, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis) {
    CrossingCheck(std::span<const Profile>(&profile, 1), origin, x_axis, y_axis).run();
}

namespace {

// True when every point lies strictly on one side of some line through the origin: the largest angular
// gap between the points' directions exceeds pi.
bool in_open_half_plane(const std::vector<Vec3>& points) {
    std::vector<double> angles;
    angles.reserve(points.size());
    for (const Vec3& p : points) {
        if (p.x == 0 && p.y == 0) return false;
        angles.push_back(std::atan2(p.y, p.x));
    }
    std::sort(angles.begin(), angles.end());
    double gap = angles.front() + 2 * std::numbers::pi - angles.back();
    for (std::size_t i = 0; i + 1 < angles.size(); ++i) gap = std::max(gap, angles[i + 1] - angles[i]);
    return gap > std::numbers::pi;
}

// Euclidean control points (x, y, 0) of a homogeneous plane row (x w, y w, w).
std::vector<Vec3> euclidean_points(const std::vector<Vec3>& homogeneous) {
    std::vector<Vec3> points;
    points.reserve(homogeneous.size());
    for (const Vec3& h : homogeneous) points.push_back(euclidean(h));
    return points;
}

// The angle a cell (homogeneous plane coordinates relative to the point) turns through about the origin.
double turning_angle(const std::vector<Vec3>& homogeneous, int halvings_left, std::string_view argument) {
    const std::vector<Vec3> points = euclidean_points(homogeneous);
    if (in_open_half_plane(points)) {
        const Vec3& a = points.front();
        const Vec3& b = points.back();
        return std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
    }
    if (halvings_left <= 0) fail(argument, "a point of one loop lies on another loop");
    const auto [left, right] = halve_bezier(homogeneous);
    return turning_angle(left, halvings_left - 1, argument) + turning_angle(right, halvings_left - 1, argument);
}

}  // namespace

int winding_number(const Profile& loop, const Vec3& point, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis,
                   std::string_view argument) {
    const Vec3 offset = point - origin;
    const Vec3 centre{dot(offset, x_axis), dot(offset, y_axis), 0.0};
    double angle = 0;
    for (const NurbsCurve& piece : loop.pieces())
        for (const BezierCurve& span : piece.bezier_segments()) {
            std::vector<Vec3> homogeneous;
            for (const Vec4& pw : span.homogeneous_points()) {
                const Vec3 p = project(pw) - origin;
                homogeneous.push_back(Vec3{dot(p, x_axis) - centre.x, dot(p, y_axis) - centre.y, 1.0} * pw.w);
            }
            for_each_certified_piece(std::vector<std::vector<Vec3>>{homogeneous}, [](const Vec3& h) { return h.z; },
                                     kMaxCellDepth, [&](const std::vector<std::vector<Vec3>>& lines, double, double) {
                                         // 50 halvings shrink a certified cell below 1e-15 of its size.
                                         angle += turning_angle(lines.front(), 50, argument);
                                     });
        }
    return static_cast<int>(std::lround(angle / (2 * std::numbers::pi)));
}

void require_no_crossings(std::span<const Profile> loops, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis) {
    CrossingCheck(loops, origin, x_axis, y_axis).run();
}

}  // namespace ratbez::detail
