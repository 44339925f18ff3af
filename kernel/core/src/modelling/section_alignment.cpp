// Sections matched by arc length from the start points of least twist; see section_alignment.hpp.
#include "modelling/section_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "geometry/bezier_merge.hpp"
#include "geometry/clamping.hpp"
#include "geometry/knot_removal.hpp"
#include "math/numeric_internal.hpp"
#include "math/vector_angle.hpp"
#include "ratbez/arc_length.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/compatible_curves.hpp"
#include "ratbez/error.hpp"

namespace ratbez::detail {

namespace {

constexpr int kSamples = 128;         // points per section for the orientation and the coarse start search
constexpr int kRefineSamples = 64;    // midpoint rule of E'(s0) in the refinement
constexpr double kMergeBreaks = 1e-9; // breakpoints closer than this (normalised length) are one
constexpr double kCornerAngle = 1e-7; // radians: a turn of the tangent this large is a corner
constexpr double kMergeTolerance = 1e-10;  // of the control size: two pieces that far from one are not one

double fraction(double s) { return s - std::floor(s); }

// A section as it will be used: its orientation chosen, its arc length tabulated, its start at normalised
// length `shift` from the curve's own start.
struct Section {
    NurbsCurve curve;
    ArcLength table;
    double shift = 0;
    explicit Section(const NurbsCurve& c) : curve(c), table(c) {}

    double parameter_at(double s) const {  // s: normalised length from the chosen start
        const double f = fraction(s + shift);
        return table.parameter(std::min(f * table.total(), table.total()));
    }
    Vec3 point_at(double s) const { return curve.point(parameter_at(s)); }
    // dC/ds with s the normalised length: the unit tangent times the length.
    Vec3 tangent_at(double s) const {
        const Vec3 d = curve.derivative(parameter_at(s), 1);
        const double speed = norm(d);
        return speed > 0 ? d * (table.total() / speed) : Vec3{};
    }
    std::vector<Vec3> samples(int count) const {
        std::vector<Vec3> points;
        for (int i = 0; i < count; ++i) points.push_back(point_at(static_cast<double>(i) / count));
        return points;
    }
};

Vec3 area_vector(const std::vector<Vec3>& p) {
    Vec3 centre{};
    for (const Vec3& q : p) centre += q;
    centre = centre / static_cast<double>(p.size());
    Vec3 a{};
    for (std::size_t i = 0; i < p.size(); ++i) a += cross(p[i] - centre, p[(i + 1) % p.size()] - centre);
    return 0.5 * a;
}

// The coarse search: the whole-sample shift j minimising sum_i |b_{i+j} - a_i|^2, and that sum.
std::pair<int, double> best_sample_shift(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    const int m = static_cast<int>(a.size());
    int best = 0;
    double best_sum = std::numeric_limits<double>::infinity();
    for (int j = 0; j < m; ++j) {
        double sum = 0;
        for (int i = 0; i < m; ++i) {
            const Vec3 d = b[to_size((i + j) % m)] - a[to_size(i)];
            sum += dot(d, d);
        }
        if (sum < best_sum) {
            best_sum = sum;
            best = j;
        }
    }
    return {best, best_sum / m};
}

// E'(s0)/2 = integral (C_b(s + s0) - C_a(s)) . C_b'(s + s0) ds by the midpoint rule (spectral for periodic
// integrands; and exactly 0 at a shift where every ruling is as short as it can be); `a_points` are C_a at
// the rule's nodes.
double twist_slope(const std::vector<Vec3>& a_points, const Section& b, double shift) {
    double sum = 0;
    for (int i = 0; i < kRefineSamples; ++i) {
        const double s = (i + 0.5) / kRefineSamples;
        const double u = b.parameter_at(s + shift);
        const std::vector<Vec3> d = b.curve.derivatives(u, 1);
        const double speed = norm(d[1]);
        if (speed > 0) sum += dot(d[0] - a_points[to_size(i)], d[1]) * (b.table.total() / speed);
    }
    return sum / kRefineSamples;
}

// The start of `next` (its shift) for the least twist against `previous` (already placed): the best
// whole-sample shift, then the root of E' between its neighbours.
double least_twist_shift(const Section& previous, const Section& next, int coarse) {
    std::vector<Vec3> a_points;
    for (int i = 0; i < kRefineSamples; ++i) a_points.push_back(previous.point_at((i + 0.5) / kRefineSamples));
    const double scale = previous.table.total() * next.table.total();
    double lo = static_cast<double>(coarse - 1) / kSamples, hi = static_cast<double>(coarse + 1) / kSamples;
    Section trial = next;
    auto slope = [&](double shift) {
        trial.shift = shift;
        return twist_slope(a_points, trial, 0.0);
    };
    double f_lo = slope(lo), f_hi = slope(hi);
    if (!(f_lo < 0 && f_hi > 0)) return static_cast<double>(coarse) / kSamples;  // no sign change: keep the sample
    // Regula falsi with the Illinois modification (the stale end's value halved), to rounding.
    int stale = 0;
    for (int iteration = 0; iteration < 60 && hi - lo > 1e-15; ++iteration) {
        const double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        const double f = slope(x);
        if (std::abs(f) <= 1e-15 * scale) return x;
        if (f < 0) {
            lo = x;
            f_lo = f;
            if (stale == -1) f_hi *= 0.5;
            stale = -1;
        } else {
            hi = x;
            f_hi = f;
            if (stale == 1) f_lo *= 0.5;
            stale = 1;
        }
    }
    return 0.5 * (lo + hi);
}

double control_size(const std::vector<NurbsCurve>& curves) {
    Box box;
    for (const NurbsCurve& c : curves)
        for (const Vec4& pw : c.homogeneous_points()) box.add(project(pw));
    return box.diagonal();
}

// A Bézier piece's homogeneous control points in the scale its points and weights were given (a curve keeps
// its own power-of-two scale inside).
std::vector<Vec4> homogeneous(const BezierCurve& bezier) {
    std::vector<Vec4> points;
    const std::vector<Vec3> xyz = bezier.points();
    const std::vector<double> w = bezier.is_rational() ? bezier.weights() : std::vector<double>(xyz.size(), 1.0);
    for (std::size_t i = 0; i < xyz.size(); ++i) points.push_back(homogenize(xyz[i], w[i]));
    return points;
}

// A part of a section between two consecutive breaks of the common parameter: its homogeneous control points
// and the knots inside it, already on the common parameter (none for one Bézier piece).
struct Stretch {
    std::vector<double> inner_knots;
    std::vector<Vec4> points;
};

// The part of `curve` over [ua, ub] on the interval [a, b] of the common parameter (its knots mapped
// linearly): the same curve in its own parameterisation, its inner knots keeping their multiplicities.
Stretch stretch(const NurbsCurve& curve, double ua, double ub, double a, double b) {
    const NurbsCurve part = restricted(curve, ua, ub);
    Stretch result{{}, part.homogeneous_points()};
    for (const double u : part.knots())
        if (u > ua && u < ub) result.inner_knots.push_back(a + (u - ua) * ((b - a) / (ub - ua)));
    return result;
}

// One degree-p curve from stretches on consecutive intervals [breaks[j], breaks[j + 1]]: knots of multiplicity
// p at the breaks; each stretch's weights scaled so that its first equals the previous stretch's last (the
// same curve, one homogeneous polygon).
NurbsCurve assemble(const std::vector<Stretch>& stretches, const std::vector<double>& breaks, int p, bool rational) {
    std::vector<double> knots(to_size(p + 1), breaks.front());
    std::vector<Vec4> points;
    for (std::size_t j = 0; j < stretches.size(); ++j) {
        std::vector<Vec4> pw = stretches[j].points;
        if (j == 0) {
            points = pw;
        } else {
            const double factor = points.back().w / pw.front().w;
            for (Vec4& q : pw) q *= factor;
            points.insert(points.end(), pw.begin() + 1, pw.end());  // the joint: the previous stretch's end
        }
        knots.insert(knots.end(), stretches[j].inner_knots.begin(), stretches[j].inner_knots.end());
        knots.insert(knots.end(), to_size(j + 1 < stretches.size() ? p : p + 1), breaks[j + 1]);
    }
    if (!rational)
        for (Vec4& q : points) q.w = 1.0;
    return NurbsCurve::from_homogeneous(p, std::move(knots), std::move(points), rational);
}

// The closed curve started at parameter u: its part over [u, end] followed by its part over [start, u],
// each keeping its knots (so its continuity) and its parameter width; the old start becomes a knot of
// multiplicity p.
NurbsCurve started_at(const NurbsCurve& curve, double u) {
    const Interval d = curve.domain();
    // At a knot within 1e-9 of the domain's width: at that knot (no sliver of a span before it).
    for (const double k : breakpoints(curve.degree(), curve.knots()))
        if (std::abs(k - u) <= 1e-9 * d.width()) u = k;
    const double joint = d.max - u, end = joint + (u - d.min);
    return assemble({stretch(curve, u, d.max, 0.0, joint), stretch(curve, d.min, u, joint, end)}, {0.0, joint, end},
                    curve.degree(), curve.is_rational());
}

// The Bézier control points of the curve between parameters ua < ub (no knot between them), in normal
// form when rational (end weights 1).
std::vector<Vec4> piece(const NurbsCurve& curve, double ua, double ub) {
    require(ub > ua, "sections", "a section stands still over a stretch of its parameter (no length to match)");
    const std::vector<BezierCurve> segments = restricted(curve, ua, ub).bezier_segments();
    require(segments.size() == 1, "sections",
            "a section has knots closer together than 1e-9 of its length; remove the sliver of a span between them");
    BezierCurve bezier = segments.front();
    if (bezier.is_rational()) bezier = bezier.normal_form();
    return homogeneous(bezier);
}

// The parameters of a section at the merged breaks: its own breakpoints where a break was merged from
// one of them (so that no piece straddles a knot), else where the normalised length reaches the break.
std::vector<double> break_parameters(const Section& section, const std::vector<double>& breaks) {
    const std::vector<double> own = breakpoints(section.curve.degree(), section.curve.knots());
    std::vector<double> own_lengths;
    for (const double u : own) own_lengths.push_back(section.table.at(u) / section.table.total());
    std::vector<double> parameters;
    for (const double b : breaks) {
        const auto near = std::min_element(own_lengths.begin(), own_lengths.end(),
                                           [&](double x, double y) { return std::abs(x - b) < std::abs(y - b); });
        parameters.push_back(std::abs(*near - b) <= kMergeBreaks ? own[to_size(static_cast<int>(near - own_lengths.begin()))]
                                                                 : section.parameter_at(b));
    }
    parameters.front() = own.front();
    parameters.back() = own.back();
    return parameters;
}

// The direction in which a Bézier piece leaves its start (or arrives at its end): along the first control
// point that differs from the end one (the end tangent of a rational or polynomial piece, its limit where
// the derivative vanishes). Zero for a piece that is a point.
Vec3 end_direction(const BezierCurve& piece, bool at_end) {
    const std::vector<Vec3> p = piece.points();
    const std::size_t n = p.size() - 1;
    const Vec3 end = at_end ? p[n] : p[0];
    for (std::size_t i = 1; i <= n; ++i) {
        const Vec3 d = at_end ? end - p[n - i] : p[i] - end;
        if (norm(d) > 0) return d;
    }
    return {};
}

bool is_corner(const BezierCurve& arriving, const BezierCurve& leaving) {
    const Vec3 in = end_direction(arriving, true), out = end_direction(leaving, false);
    if (norm(in) == 0 || norm(out) == 0) return true;  // a piece that is a point: no tangent to continue
    return angle_between(in, out) > kCornerAngle;
}

// The corners of a closed section (is_corner), as normalised lengths from its start; 0 first when its start is one.
std::vector<double> corner_lengths(const Section& section) {
    const std::vector<double> breaks = breakpoints(section.curve.degree(), section.curve.knots());
    const std::vector<BezierCurve> segments = section.curve.bezier_segments();
    std::vector<double> corners;
    for (std::size_t j = 0; j + 1 < breaks.size(); ++j)
        if (is_corner(j == 0 ? segments.back() : segments[j - 1], segments[j]))
            corners.push_back(section.table.at(breaks[j]) / section.table.total());
    return corners;
}

// True when the curve is C0 at u in its own parameter: u is a knot of multiplicity p or more (the knots
// of `curve` at the multiplicities its continuity needs: without_removable_knots).
bool is_c0_at(const NurbsCurve& curve, double u) {
    const std::vector<double>& knots = curve.knots();
    return std::count(knots.begin(), knots.end(), u) >= curve.degree();
}

// Removes every inner break where each section's pieces on both sides are parts of one Bézier piece of their
// degree (bezier_merge.hpp), and merges them: the break was some section's own joint (a circle's arcs meet
// every 120 degrees) that the others only had to be cut at. Left in place, every such break would be a knot of
// multiplicity p across the whole loft, a C0 line OpenCASCADE takes as a face edge. A polynomial section keeps
// only merged pieces whose weights come out 1. The break at the start of closed sections (the seam) stays.
void merge_smooth_breaks(std::vector<std::vector<std::vector<Vec4>>>& pieces, std::vector<double>& breaks,
                         const std::vector<bool>& rational, double tolerance) {
    std::size_t j = 1;  // break j joins piece j - 1 to piece j
    while (j + 1 < breaks.size()) {
        std::vector<std::vector<Vec4>> joined;
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            std::optional<std::vector<Vec4>> one = merged_bezier(pieces[k][j - 1], pieces[k][j], tolerance);
            if (one && !rational[k] &&
                std::any_of(one->begin(), one->end(), [](const Vec4& q) { return std::abs(q.w - 1) > 1e-12; }))
                one.reset();
            if (!one) break;
            joined.push_back(std::move(*one));
        }
        if (joined.size() < pieces.size()) {
            ++j;
            continue;
        }
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            pieces[k][j - 1] = std::move(joined[k]);
            pieces[k].erase(pieces[k].begin() + static_cast<std::ptrdiff_t>(j));
        }
        breaks.erase(breaks.begin() + static_cast<std::ptrdiff_t>(j));
    }
}

}  // namespace

AlignedSections align_sections(const std::vector<NurbsCurve>& input, const std::string& argument, bool keep_orientation) {
    const double size = control_size(input);
    const double closure = 1e-9 * size;
    std::vector<NurbsCurve> curves;
    for (const NurbsCurve& c : input) curves.push_back(clamped_ends(c));
    const bool closed = distance(curves.front().start_point(), curves.front().end_point()) <= closure;
    for (std::size_t k = 0; k < curves.size(); ++k) {
        const bool this_closed = distance(curves[k].start_point(), curves[k].end_point()) <= closure;
        require(this_closed == closed, argument, [&] {
            return "section " + std::to_string(k) + " is " + (this_closed ? "closed" : "open") + " but section 0 is " +
                   (closed ? "closed" : "open") + "; aligned sections are all closed or all open (align=False joins them by parameter)";
        });
    }

    std::vector<Section> sections;
    for (std::size_t k = 0; k < curves.size(); ++k) {
        sections.emplace_back(curves[k]);
        require(sections.back().table.total() > 1e-12 * size, argument,
                [&] { return "section " + std::to_string(k) + " has no length (a point cannot be aligned)"; });
    }

    // Orientation and start, each section against the one before it.
    for (std::size_t k = 1; k < sections.size(); ++k) {
        const Section& previous = sections[k - 1];
        const std::vector<Vec3> a = previous.samples(kSamples);
        if (!closed) {
            const Vec3 a0 = previous.point_at(0.0), a1 = previous.curve.end_point();
            const Vec3 b0 = sections[k].curve.start_point(), b1 = sections[k].curve.end_point();
            if (distance(a0, b1) + distance(a1, b0) < distance(a0, b0) + distance(a1, b1))
                sections[k] = Section(sections[k].curve.reversed());
            continue;
        }
        std::optional<bool> reverse;
        if (keep_orientation) {
            reverse = false;
        } else {
            const Vec3 area_a = area_vector(a), area_b = area_vector(sections[k].samples(kSamples));
            const double scale = 0.1 * sections[k - 1].table.total() * sections[k].table.total() / (4 * std::numbers::pi);
            const double d = dot(area_a, area_b) / std::max(norm(area_a) * norm(area_b), 1e-300);
            if (norm(area_a) > scale && norm(area_b) > scale && std::abs(d) > 0.1) reverse = d < 0;
        }
        Section forward = sections[k];
        auto [shift, twist] = best_sample_shift(a, forward.samples(kSamples));
        if (!reverse.has_value() || *reverse) {
            Section backward(sections[k].curve.reversed());
            const auto [back_shift, back_twist] = best_sample_shift(a, backward.samples(kSamples));
            if (reverse.has_value() || back_twist < twist) {
                forward = backward;
                shift = back_shift;
            }
        }
        forward.shift = least_twist_shift(previous, forward, shift);
        forward.shift = fraction(forward.shift);
        sections[k] = forward;
    }

    // Every closed section restarted at its chosen start (its old start becomes an interior break).
    for (Section& s : sections) {
        if (s.shift == 0) continue;
        const double u = s.parameter_at(0.0);
        const Interval d = s.curve.domain();
        if (u - d.min <= 1e-9 * d.width() || d.max - u <= 1e-9 * d.width()) {
            s.shift = 0;
            continue;
        }
        s = Section(started_at(s.curve, u));
    }

    // The seam at a corner, when some section has one and none has it at the chosen start: every section restarted
    // at the first corner of any. A seam is a break that always stays, and there each section's pieces are in
    // normal form on both sides, their weights continuous but not smooth across it: a circle's seam halfway along a
    // square's side skinned into a fold between the side faces, tangent only at the sections (circle -> square ->
    // circle: 1.3 degrees halfway; OpenCASCADE took the edge for a tangent one, its inward Offset came out null and
    // its Fillet raised). At a corner the side faces meet at an edge anyway, and the old start merges away below.
    if (closed) {
        bool seam_at_corner = false;
        double first = 1.0;
        for (const Section& s : sections) {
            const std::vector<double> corners = corner_lengths(s);
            if (!corners.empty() && corners.front() <= kMergeBreaks) seam_at_corner = true;
            for (const double c : corners)
                if (c > kMergeBreaks && 1.0 - c > kMergeBreaks) first = std::min(first, c);
        }
        if (!seam_at_corner && first < 1.0)
            for (Section& s : sections) s = Section(started_at(s.curve, s.parameter_at(first)));
    }

    // The merged breakpoints in normalised length from each section's start.
    std::vector<double> breaks;
    for (const Section& s : sections)
        for (const double u : breakpoints(s.curve.degree(), s.curve.knots())) breaks.push_back(s.table.at(u) / s.table.total());
    std::sort(breaks.begin(), breaks.end());
    std::vector<double> merged{0.0};
    for (const double b : breaks)
        if (b - merged.back() > kMergeBreaks && 1.0 - b > kMergeBreaks) merged.push_back(b);
    merged.push_back(1.0);

    std::vector<std::vector<std::vector<Vec4>>> pieces(sections.size());
    for (std::size_t k = 0; k < sections.size(); ++k) {
        const std::vector<double> u = break_parameters(sections[k], merged);
        try {
            for (std::size_t j = 0; j + 1 < merged.size(); ++j) pieces[k].push_back(piece(sections[k].curve, u[j], u[j + 1]));
        } catch (const Error& e) {
            throw e.renamed("sections", argument);
        }
    }
    std::vector<bool> rational;
    for (const Section& s : sections) rational.push_back(s.curve.is_rational());
    merge_smooth_breaks(pieces, merged, rational, kMergeTolerance * size);

    // The breaks that stay: the ends, and every break where some section is C0 in its own parameter (a corner,
    // a circle's arc joint, a line meeting an arc). Between two of them every section runs on its own
    // parameter, mapped linearly (a stretch); a single piece left there by the merging keeps its normal form.
    std::vector<NurbsCurve> own;  // each knot at the multiplicity the section's continuity needs
    std::vector<std::vector<double>> at;
    for (const Section& s : sections) {
        own.push_back(without_removable_knots(s.curve, kMergeTolerance * size));
        at.push_back(break_parameters(s, merged));
    }
    std::vector<std::size_t> kept{0};
    for (std::size_t j = 1; j + 1 < merged.size(); ++j)
        for (std::size_t k = 0; k < sections.size(); ++k)
            if (is_c0_at(own[k], at[k][j])) {
                kept.push_back(j);
                break;
            }
    kept.push_back(merged.size() - 1);

    AlignedSections result;
    result.closed = closed;
    for (const std::size_t j : kept) result.breaks.push_back(merged[j]);
    std::vector<NurbsCurve> aligned;
    for (std::size_t k = 0; k < sections.size(); ++k) {
        std::vector<Stretch> stretches;
        for (std::size_t i = 0; i + 1 < kept.size(); ++i) {
            const std::size_t a = kept[i], b = kept[i + 1];
            stretches.push_back(b == a + 1 ? Stretch{{}, pieces[k][a]}
                                           : stretch(own[k], at[k][a], at[k][b], merged[a], merged[b]));
        }
        aligned.push_back(assemble(stretches, result.breaks, own[k].degree(), rational[k]));
    }
    result.curves = make_compatible(aligned, argument);
    return result;
}

std::vector<NurbsCurve> restarted_at(const std::vector<NurbsCurve>& sections, double parameter) {
    std::vector<NurbsCurve> result;
    for (const NurbsCurve& c : sections) result.push_back(started_at(c, parameter));
    return result;
}

std::vector<double> full_creases(const std::vector<NurbsCurve>& sections, bool closed) {
    const NurbsCurve& first = sections.front();
    const std::vector<double> breaks = breakpoints(first.degree(), first.knots());
    std::vector<std::vector<BezierCurve>> segments;
    for (const NurbsCurve& c : sections) segments.push_back(c.bezier_segments());
    std::vector<double> creases;
    // Break j joins segment j - 1 to segment j (the last to the first at 0 for a closed section).
    for (std::size_t j = closed ? 0 : 1; j + 1 < breaks.size(); ++j) {
        bool everywhere = true;
        for (const std::vector<BezierCurve>& s : segments)
            if (!is_corner(j == 0 ? s.back() : s[j - 1], s[j])) {
                everywhere = false;
                break;
            }
        if (everywhere) creases.push_back(breaks[j]);
    }
    return creases;
}

}  // namespace ratbez::detail
