// Sweeps along a path with a rotation-minimising frame; see sweep.hpp for the method and its guarantees.
#include "ratbez/sweep.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "geometry/clamping.hpp"
#include "geometry/knot_removal.hpp"
#include "math/degrees.hpp"
#include "math/numeric_internal.hpp"
#include "math/vector_angle.hpp"
#include "modelling/planar_profile.hpp"
#include "modelling/embedding_check.hpp"
#include "modelling/tube_shell.hpp"
#include "ratbez/affine_map.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/degree_elevation.hpp"
#include "ratbez/error.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/frame.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/rotation_minimizing_frame.hpp"

namespace ratbez {

namespace {

using detail::number;

constexpr double kPi = std::numbers::pi;
// Control points this close to a line or a circle (relative to the path's size) make it one: far above the
// rounding of exact constructions (~1e-16), far below any deviation drawn on purpose.
constexpr double kExactRelative = 1e-12;
// Tangents differing by more than this at a knot are a corner.
constexpr double kCornerAngle = 1e-9;
// Budgets: reference frame samples and Hermite intervals, so that an unreachable tolerance is an Error.
constexpr std::size_t kMaxReferenceSamples = 4'000'000;
constexpr std::size_t kMaxIntervals = 200'000;
constexpr int kErrorSamples = 8;          // per interval while refining
constexpr int kVerificationSamples = 24;  // per interval for the reported error

Vec3 unit(const Vec3& a) { return a / norm(a); }

using detail::angle_between;

// a rotated about the unit axis by the angle (cos c, sin s), Rodrigues' formula.
Vec3 rotated(const Vec3& a, const Vec3& axis, double c, double s) {
    return a * c + cross(axis, a) * s + axis * (dot(axis, a) * (1 - c));
}

// The surface with u and v exchanged (net transposed): the revolution's rotation becomes the v direction.
NurbsSurface transposed(const NurbsSurface& s) {
    std::vector<Vec4> net(s.homogeneous_points().size());
    for (int i = 0; i < s.rows(); ++i)
        for (int j = 0; j < s.columns(); ++j)
            net[static_cast<std::size_t>(j * s.rows() + i)] = s.homogeneous_point(i, j);
    return NurbsSurface::from_homogeneous(s.degree_v(), s.degree_u(), s.knots_v(), s.knots_u(), std::move(net),
                                          s.is_rational());
}

// ---- the path, span by span

struct PathPoint {
    Vec3 x, d1, d2, d3;  // position and the first three derivatives in the path's parameter
};

// The path as its Bézier spans, each evaluated on its own (so derivatives at a span's ends are one-sided).
class Path {
public:
    explicit Path(const NurbsCurve& curve) : curve_(curve), breaks_(breakpoints(curve.degree(), curve.knots())) {
        spans_ = curve.bezier_segments();
        size_ = curve.control_box().diagonal();
    }
    std::size_t spans() const { return spans_.size(); }
    double start(std::size_t k) const { return breaks_[k]; }
    double end(std::size_t k) const { return breaks_[k + 1]; }
    double size() const { return size_; }
    const NurbsCurve& curve() const { return curve_; }

    PathPoint at(std::size_t span, double t) const {
        const double a = breaks_[span], h = breaks_[span + 1] - a;
        const double s = std::clamp((t - a) / h, 0.0, 1.0);
        const std::vector<Vec3> d = spans_[span].derivatives(s, 3);
        return {d[0], d[1] / h, d[2] / (h * h), d[3] / (h * h * h)};
    }

private:
    NurbsCurve curve_;
    std::vector<double> breaks_;
    std::vector<BezierCurve> spans_;
    double size_ = 0;
};

// ---- exact cases

struct Line {
    Vec3 displacement;
};

std::optional<Line> as_line(const Path& path) {
    const NurbsCurve& c = path.curve();
    const Vec3 a = c.start_point(), b = c.end_point();
    const double length = distance(a, b);
    if (length <= 1e-9 * path.size()) return std::nullopt;
    const Vec3 d = (b - a) / length;
    double previous = -std::numeric_limits<double>::infinity();
    for (const Vec4& pw : c.homogeneous_points()) {
        const Vec3 r = project(pw) - a;
        if (norm(r - d * dot(r, d)) > kExactRelative * path.size()) return std::nullopt;
        if (dot(r, d) < previous) return std::nullopt;  // not advancing monotonically: let the general method judge
        previous = dot(r, d);
    }
    return Line{b - a};
}

struct Arc {
    Vec3 centre, axis;
    double radius, angle_deg;
};

std::optional<Arc> as_arc(const Path& path) {
    const NurbsCurve& c = path.curve();
    const Interval d = c.domain();
    const Vec3 p0 = c.point(d.min), p1 = c.point(d.min + d.width() / 3), p2 = c.point(d.min + 2 * d.width() / 3);
    // The circle through three points: its centre in their plane, equidistant from them.
    const Vec3 a = p1 - p0, b = p2 - p0;
    const Vec3 n = cross(a, b);
    const double nn = dot(n, n);
    const double tol = kExactRelative * path.size();
    if (!(nn > 1e-18 * std::pow(path.size(), 4))) return std::nullopt;
    const Vec3 centre = p0 + (cross(n, a) * dot(b, b) + cross(b, n) * dot(a, a)) / (2 * nn);
    const double radius = distance(centre, p0);
    const Vec3 normal = n / std::sqrt(nn);
    for (const Vec4& pw : c.homogeneous_points())
        if (std::abs(dot(project(pw) - p0, normal)) > tol) return std::nullopt;
    // On the circle at 2p + 3 points per span (2p + 1 certify a degree-p rational span), turning one way.
    const int samples = 2 * c.degree() + 3;
    const Vec3 axis = dot(cross(p0 - centre, path.at(0, d.min).d1), normal) >= 0 ? normal : -normal;
    double angle = 0;
    Vec3 previous = p0 - centre;
    for (std::size_t k = 0; k < path.spans(); ++k)
        for (int i = 1; i <= samples; ++i) {
            const double t = path.start(k) + (path.end(k) - path.start(k)) * i / samples;
            const PathPoint q = path.at(k, t);
            const Vec3 r = q.x - centre;
            if (std::abs(norm(r) - radius) > tol) return std::nullopt;
            if (!(dot(cross(r, q.d1), axis) > 0)) return std::nullopt;
            const double step = std::atan2(dot(cross(previous, r), axis), dot(previous, r));
            if (step < 0) return std::nullopt;
            angle += step;
            previous = r;
        }
    const double degrees = angle * 180 / kPi;
    const bool closed = distance(c.start_point(), c.end_point()) <= 1e-9 * path.size();
    if (closed) {
        if (std::abs(degrees - 360.0) > 1e-6) return std::nullopt;  // round more than once: refused later
        return Arc{centre, axis, radius, 360.0};
    }
    if (degrees >= 360.0) return std::nullopt;  // more than a turn: the general method refuses the overlap
    return Arc{centre, axis, radius, degrees};
}

// ---- a path of lines and arcs, piece by piece

// One piece of a path of lines and arcs (a sketch's line and tangent arc): consecutive spans on one line or one
// circle, merged.
struct Piece {
    std::optional<Line> line;
    std::optional<Arc> arc;
    double start = 0;  // the path parameter where it starts (for messages)
};

// The path's spans each a line or an arc, consecutive spans of the same line or circle merged; nullopt when a
// span is neither (the general method then approximates).
std::optional<std::vector<Piece>> as_lines_and_arcs(const Path& path) {
    const double tol = 1e3 * kExactRelative * path.size();
    std::vector<Piece> pieces;
    const std::vector<BezierCurve> spans = path.curve().bezier_segments();
    for (std::size_t k = 0; k < spans.size(); ++k) {
        const Path one(NurbsCurve::from_bezier(spans[k]));
        if (const std::optional<Line> line = as_line(one)) {
            if (!pieces.empty() && pieces.back().line &&
                angle_between(pieces.back().line->displacement, line->displacement) <= kCornerAngle)
                pieces.back().line->displacement = pieces.back().line->displacement + line->displacement;
            else
                pieces.push_back({line, std::nullopt, path.start(k)});
        } else if (const std::optional<Arc> arc = as_arc(one)) {
            Piece* last = pieces.empty() ? nullptr : &pieces.back();
            if (last && last->arc && distance(last->arc->centre, arc->centre) <= tol &&
                distance(last->arc->axis, arc->axis) <= kCornerAngle && last->arc->angle_deg + arc->angle_deg < 360.0)
                last->arc->angle_deg += arc->angle_deg;
            else
                pieces.push_back({std::nullopt, arc, path.start(k)});
        } else {
            return std::nullopt;
        }
    }
    return pieces;
}

// Surfaces of one section, one per piece (v on [0, 1] each), end to end in v: raised to one degree p, v of
// piece k on [start[k], start[k + 1]], the joints knots of multiplicity p (C0: the speed along the path may
// jump there; the surface itself is tangent-continuous as the path is) and each shared column kept once.
NurbsSurface joined_along_v(std::vector<NurbsSurface> pieces, const std::vector<double>& start) {
    int p = 0;
    for (const NurbsSurface& s : pieces) p = std::max(p, s.degree_v());
    for (NurbsSurface& s : pieces)
        if (s.degree_v() < p) s = elevate_degree_v(s, p - s.degree_v());
    const NurbsSurface& first = pieces.front();
    const int rows = first.rows();
    std::vector<std::vector<Vec4>> columns_of_row(static_cast<std::size_t>(rows));
    std::vector<double> knots(static_cast<std::size_t>(p + 1), start.front());
    bool rational = false;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const NurbsSurface& s = pieces[k];
        rational = rational || s.is_rational();
        const Interval d = s.domain_v();
        const auto mapped = [&](double v) { return start[k] + (start[k + 1] - start[k]) * (v - d.min) / d.width(); };
        for (double v : s.knots_v())
            if (v > d.min && v < d.max) knots.push_back(mapped(v));
        knots.insert(knots.end(), static_cast<std::size_t>(k + 1 < pieces.size() ? p : p + 1), start[k + 1]);
        for (int i = 0; i < rows; ++i)
            for (int j = k == 0 ? 0 : 1; j < s.columns(); ++j) columns_of_row[static_cast<std::size_t>(i)].push_back(s.homogeneous_point(i, j));
    }
    std::vector<Vec4> net;
    for (const std::vector<Vec4>& row : columns_of_row) net.insert(net.end(), row.begin(), row.end());
    return NurbsSurface::from_homogeneous(first.degree_u(), p, first.knots_u(), std::move(knots), std::move(net), rational);
}

// The parts of a surface between its joints: v knots of full multiplicity p (joined_along_v's), where the
// surface is its parts end to end, so a part is a run of its columns (the joint's column shared with the next)
// on its knots between the joints, clamped there. Exact: no control point is computed.
std::vector<NurbsSurface> split_at_joints_v(const NurbsSurface& surface, const std::vector<double>& joints) {
    const int p = surface.degree_v();
    const std::vector<double>& knots = surface.knots_v();
    std::vector<double> ends = joints;
    ends.push_back(knots.back());
    std::vector<NurbsSurface> parts;
    double start = knots.front();
    std::size_t first_column = 0;
    for (const double end : ends) {
        std::vector<double> part_knots(static_cast<std::size_t>(p + 1), start);
        for (double knot : knots)
            if (knot > start && knot < end) part_knots.push_back(knot);
        part_knots.insert(part_knots.end(), static_cast<std::size_t>(p + 1), end);
        const std::size_t columns = part_knots.size() - static_cast<std::size_t>(p) - 1;
        std::vector<Vec4> net;
        for (int i = 0; i < surface.rows(); ++i)
            for (std::size_t c = 0; c < columns; ++c) net.push_back(surface.homogeneous_point(i, static_cast<int>(first_column + c)));
        parts.push_back(NurbsSurface::from_homogeneous(surface.degree_u(), p, surface.knots_u(), std::move(part_knots),
                                                       std::move(net), surface.is_rational()));
        first_column += columns - 1;
        start = end;
    }
    return parts;
}

// ---- the rotation-minimising frame along a general path

// The frame at a path parameter with its first two derivatives in that parameter (the trajectories' Hermite
// data): position x, unit tangent t, the rotation-minimising normals r and s = t x r.
struct FrameData {
    Vec3 x, x1, x2;
    Vec3 t, t1, t2;
    Vec3 r, r1, r2, s, s1, s2;
};

struct Reference {
    double t;
    std::size_t span;
    Vec3 x, tangent, r;
};

class MovingFrame {
public:
    MovingFrame(const Path& path, const Vec3& r0, double step_angle, bool closed)
        : path_(path), t0_(path.start(0)), t1_(path.end(path.spans() - 1)) {
        // Reference samples: each span cut so that the tangent turns by at most step_angle per step (judged
        // on 32 sub-intervals), shared at the span joints.
        for (std::size_t k = 0; k < path.spans(); ++k) {
            constexpr int probes = 32;
            const double a = path.start(k), h = path.end(k) - a;
            if (k == 0) add(k, a);
            Vec3 previous = unit(path.at(k, a).d1);
            for (int i = 1; i <= probes; ++i) {
                const double ta = a + h * (i - 1) / probes, tb = i == probes ? path.end(k) : a + h * i / probes;
                const Vec3 tangent = unit(path.at(k, tb).d1);
                const int steps = std::max(1, static_cast<int>(std::ceil(angle_between(previous, tangent) / step_angle)));
                for (int j = 1; j <= steps; ++j) add(k, j == steps ? tb : ta + (tb - ta) * j / steps);
                previous = tangent;
            }
            require(samples_.size() <= kMaxReferenceSamples, "tolerance",
                    "needs more than 4 million frame samples along the path: too fine for this path");
        }
        std::vector<Vec3> points, tangents;
        for (const Reference& s : samples_) {
            points.push_back(s.x);
            tangents.push_back(s.tangent);
        }
        const std::vector<Vec3> r = rotation_minimizing_frame(points, tangents, r0);
        for (std::size_t j = 0; j < samples_.size(); ++j) samples_[j].r = r[j];
        // Richardson estimate of the frame's error: double reflection is fourth order, so the run on every
        // other sample differs from this one by about 15 times this one's error.
        std::vector<Vec3> half_points, half_tangents;
        for (std::size_t j = 0; j < samples_.size(); j += 2) {
            half_points.push_back(points[j]);
            half_tangents.push_back(tangents[j]);
        }
        if ((samples_.size() - 1) % 2 != 0) {
            half_points.push_back(points.back());
            half_tangents.push_back(tangents.back());
        }
        const Vec3 coarse = rotation_minimizing_frame(half_points, half_tangents, r0).back();
        error_ = norm(coarse - r.back()) / 15;
        if (closed) {
            // The holonomy: the angle from r_0 to the returned r about the (common) tangent.
            const Vec3 t = samples_.front().tangent, back = samples_.back().r;
            holonomy_ = std::atan2(dot(cross(r0, back), t), dot(r0, back));
        }
    }

    // The angle by which the frame is turned back at t (0 on an open path), and its derivative.
    double twist(double t) const { return -holonomy_ * (t - t0_) / (t1_ - t0_); }
    double twist_rate() const { return -holonomy_ / (t1_ - t0_); }
    double error() const { return error_; }
    const std::vector<Reference>& samples() const { return samples_; }

    // The frame and its derivative at t in a span: one double reflection from the reference sample below.
    FrameData at(std::size_t span, double t) const {
        const PathPoint p = path_.at(span, t);
        FrameData f;
        f.x = p.x;
        f.x1 = p.d1;
        f.x2 = p.d2;
        // sigma t = x' with sigma = |x'|, differentiated twice: t' = (x'' - sigma' t) / sigma,
        // t'' = (x''' - sigma'' t - 2 sigma' t') / sigma, sigma' = x'' . t, sigma'' = x''' . t + x'' . t'.
        const double sigma = norm(p.d1);
        f.t = p.d1 / sigma;
        const double sigma1 = dot(p.d2, f.t);
        f.t1 = (p.d2 - f.t * sigma1) / sigma;
        const double sigma2 = dot(p.d3, f.t) + dot(p.d2, f.t1);
        f.t2 = (p.d3 - f.t * sigma2 - f.t1 * (2 * sigma1)) / sigma;
        const auto above = std::upper_bound(samples_.begin(), samples_.end(), t,
                                            [](double value, const Reference& s) { return value < s.t; });
        const Reference& below = *(above == samples_.begin() ? above : above - 1);
        const Vec3 r = below.t == t ? below.r : double_reflection(below.x, below.tangent, below.r, f.x, f.t);
        const Vec3 s = cross(f.t, r);
        // No spin about the tangent: r' = -(t' . r) t, so r'' = -(t'' . r) t - (t' . r) t' (t' . r' = 0);
        // the same for s = t x r.
        const Vec3 r1 = f.t * -dot(f.t1, r), s1 = f.t * -dot(f.t1, s);
        const Vec3 r2 = f.t * -dot(f.t2, r) - f.t1 * dot(f.t1, r), s2 = f.t * -dot(f.t2, s) - f.t1 * dot(f.t1, s);
        // Turned back by phi (linear in t, phi' = w): r~ = c r + sn s, s~ = c s - sn r, and
        // r~' = c r' + sn s' + w s~, r~'' = c r'' + sn s'' + 2 w (c s' - sn r') - w^2 r~ (s~ alike).
        const double phi = twist(t), w = twist_rate();
        const double c = std::cos(phi), sn = std::sin(phi);
        f.r = r * c + s * sn;
        f.s = s * c - r * sn;
        f.r1 = r1 * c + s1 * sn + f.s * w;
        f.s1 = s1 * c - r1 * sn - f.r * w;
        f.r2 = r2 * c + s2 * sn + (s1 * c - r1 * sn) * (2 * w) - f.r * (w * w);
        f.s2 = s2 * c - r2 * sn - (r1 * c + s1 * sn) * (2 * w) - f.s * (w * w);
        return f;
    }

private:
    void add(std::size_t span, double t) {
        const PathPoint p = path_.at(span, t);
        samples_.push_back({t, span, p.x, unit(p.d1), {}});
    }

    const Path& path_;
    double t0_, t1_;
    std::vector<Reference> samples_;
    double error_ = 0, holonomy_ = 0;
};

// A section point's local coordinates (in the start frame) and its position and velocity at a frame.
struct Local {
    double x, y, z;
};
Vec3 position(const FrameData& f, const Local& l) { return f.x + f.r * l.x + f.s * l.y + f.t * l.z; }
Vec3 velocity(const FrameData& f, const Local& l) { return f.x1 + f.r1 * l.x + f.s1 * l.y + f.t1 * l.z; }
Vec3 acceleration(const FrameData& f, const Local& l) { return f.x2 + f.r2 * l.x + f.s2 * l.y + f.t2 * l.z; }

// ---- checks shared by every method

void check_path(const Path& path) {
    const double size = path.size();
    require(size > 0, "path", "is a single point");
    for (std::size_t k = 0; k < path.spans(); ++k) {
        // Speed at 2p + 1 points of every span (a stop would leave the frame undefined).
        const int samples = 2 * path.curve().degree() + 1;
        for (int i = 0; i <= samples; ++i) {
            const double t = path.start(k) + (path.end(k) - path.start(k)) * i / samples;
            const double speed = norm(path.at(k, t).d1);
            require(speed > 1e-12 * size / (path.end(k) - path.start(k)), "path", [&] {
                return "stops (its speed is 0) at parameter " + number(t) + "; a sweep needs a regular path";
            });
        }
        if (k + 1 < path.spans()) {
            const double t = path.end(k);
            const double angle = angle_between(path.at(k, t).d1, path.at(k + 1, t).d1);
            require(angle <= kCornerAngle, "path", [&] {
                return "has a corner at parameter " + number(t) + " (its tangent turns by " + number(angle * 180 / kPi) +
                       " degrees there); a sweep needs a tangent-continuous path";
            });
        }
    }
}

bool path_is_closed(const Path& path) {
    const NurbsCurve& c = path.curve();
    if (distance(c.start_point(), c.end_point()) > 1e-9 * path.size()) return false;
    const Vec3 first = path.at(0, path.start(0)).d1;
    const Vec3 last = path.at(path.spans() - 1, path.end(path.spans() - 1)).d1;
    const double angle = angle_between(first, last);
    require(angle <= kCornerAngle, "path", [&] {
        return "is closed with a corner where it starts and ends (its tangent turns by " + number(angle * 180 / kPi) +
               " degrees there); a closed sweep needs the same tangent at both ends";
    });
    return true;
}

// The section's largest reach into a bend: kappa * max_i (L_i . N) must stay below 1 (the swept surface's
// v-derivative, |x'| (1 - kappa L . N) t + ..., would vanish and the surface fold over itself).
void check_bend(const FrameData& f, const std::vector<Local>& locals, double parameter, const char* argument) {
    const double speed = norm(f.x1);
    const double curvature = norm(f.t1) / speed;
    if (curvature == 0) return;
    const Vec3 n = f.t1 / norm(f.t1);
    double reach = 0;
    for (const Local& l : locals) reach = std::max(reach, dot(f.r * l.x + f.s * l.y, n));
    require(curvature * reach < 1 - 1e-9, argument, [&] {
        return "reaches " + number(reach) + " into a bend of the path whose radius of curvature is " +
               number(1 / curvature) + " (at path parameter " + number(parameter) +
               "): the swept surface would intersect itself";
    });
}

// Two parts of the path more than pi rho apart along it (half a turn around a tube of radius rho) must stay
// 2 rho apart, else the swept sections can meet. A grid of cells 2 rho wide finds the near pairs.
void check_far_parts(const std::vector<Reference>& samples, double rho, bool closed, const char* argument) {
    if (rho <= 0) return;
    std::vector<double> arc(samples.size(), 0.0);
    for (std::size_t j = 1; j < samples.size(); ++j) arc[j] = arc[j - 1] + distance(samples[j - 1].x, samples[j].x);
    const double length = arc.back();
    const double cell = 2 * rho;
    auto key = [&](const Vec3& p) {
        const auto ix = static_cast<long long>(std::floor(p.x / cell)), iy = static_cast<long long>(std::floor(p.y / cell)),
                   iz = static_cast<long long>(std::floor(p.z / cell));
        return std::array<long long, 3>{ix, iy, iz};
    };
    struct Hash {
        std::size_t operator()(const std::array<long long, 3>& k) const {
            return std::hash<long long>()(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
        }
    };
    // Thin the samples to about rho / 4 apart: enough to see a 2 rho approach, and O(n) cells.
    std::vector<std::size_t> kept;
    for (std::size_t j = 0; j < samples.size(); ++j)
        if (kept.empty() || arc[j] - arc[kept.back()] >= rho / 4 || j + 1 == samples.size()) kept.push_back(j);
    std::unordered_map<std::array<long long, 3>, std::vector<std::size_t>, Hash> grid;
    for (const std::size_t j : kept) grid[key(samples[j].x)].push_back(j);
    for (const std::size_t j : kept) {
        const auto base = key(samples[j].x);
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz) {
                    const auto it = grid.find({base[0] + dx, base[1] + dy, base[2] + dz});
                    if (it == grid.end()) continue;
                    for (const std::size_t i : it->second) {
                        if (i <= j) continue;
                        double along = arc[i] - arc[j];
                        if (closed) along = std::min(along, length - along);
                        if (along <= kPi * rho) continue;
                        const double gap = distance(samples[i].x, samples[j].x);
                        // The thinned samples stand for path pieces rho / 4 long: allow for that.
                        require(gap >= 2 * rho - rho / 4, argument, [&] {
                            return "sweeps within " + number(gap) + " of itself: the path at parameters " +
                                   number(samples[j].t) + " and " + number(samples[i].t) +
                                   " comes closer than twice the section's reach " + number(rho) +
                                   " (the swept surface would intersect itself)";
                        });
                    }
                }
    }
}

// ---- the approximation

// The trajectories are quintic: Hermite data Q, Q', Q'' at the interval ends (error O(h^6)), joined C2
// inside a path span.
constexpr int kDegree = 5;

struct Interval3 {
    std::size_t span;
    double a, b;
};

using Quintic = std::array<Vec3, kDegree + 1>;

// Quintic Hermite data of every trajectory on one interval as Bezier points: with h = b - a and
// C'(0) = 5 (B1 - B0) / h, C''(0) = 20 (B2 - 2 B1 + B0) / h^2 (and mirrored at the end),
// B1 = Q + h Q' / 5, B2 = Q + 2 h Q' / 5 + h^2 Q'' / 20.
struct HermitePiece {
    std::vector<Quintic> bezier;
};

HermitePiece hermite_piece(const MovingFrame& frame, const Interval3& iv, const std::vector<Local>& locals) {
    const FrameData fa = frame.at(iv.span, iv.a), fb = frame.at(iv.span, iv.b);
    const double h = iv.b - iv.a;
    HermitePiece piece;
    piece.bezier.reserve(locals.size());
    for (const Local& l : locals) {
        const Vec3 q0 = position(fa, l), d0 = velocity(fa, l) * h, a0 = acceleration(fa, l) * (h * h);
        const Vec3 q1 = position(fb, l), d1 = velocity(fb, l) * h, a1 = acceleration(fb, l) * (h * h);
        piece.bezier.push_back({q0, q0 + d0 / 5.0, q0 + d0 * 0.4 + a0 / 20.0, q1 - d1 * 0.4 + a1 / 20.0, q1 - d1 / 5.0, q1});
    }
    return piece;
}

Vec3 quintic(const Quintic& b, double s) {
    const double u = 1 - s, s2 = s * s, u2 = u * u;
    return b[0] * (u2 * u2 * u) + b[1] * (5 * u2 * u2 * s) + b[2] * (10 * u2 * u * s2) + b[3] * (10 * u2 * s2 * s) +
           b[4] * (5 * u * s2 * s2) + b[5] * (s2 * s2 * s);
}

double piece_error(const MovingFrame& frame, const Interval3& iv, const HermitePiece& piece,
                   const std::vector<Local>& locals, int samples) {
    double worst = 0;
    for (int k = 1; k <= samples; ++k) {
        const double s = static_cast<double>(k) / (samples + 1);
        const FrameData f = frame.at(iv.span, iv.a + (iv.b - iv.a) * s);
        for (std::size_t i = 0; i < locals.size(); ++i)
            worst = std::max(worst, distance(quintic(piece.bezier[i], s), position(f, locals[i])));
    }
    return worst;
}

struct Approximation {
    std::vector<Interval3> intervals;
    std::vector<HermitePiece> pieces;
};

// Hermite pieces on `intervals` (in order), each halved until its error at kErrorSamples points is below
// `budget`.
Approximation approximate(const std::vector<Interval3>& intervals, const MovingFrame& frame,
                          const std::vector<Local>& locals, double budget) {
    std::vector<Interval3> pending(intervals.rbegin(), intervals.rend());
    // Depth first from the path's start, so that the accepted intervals come out in order.
    Approximation result;
    while (!pending.empty()) {
        const Interval3 iv = pending.back();
        pending.pop_back();
        HermitePiece piece = hermite_piece(frame, iv, locals);
        const double error = piece_error(frame, iv, piece, locals, kErrorSamples);
        const double mid = 0.5 * (iv.a + iv.b);
        if (error > budget && mid > iv.a && mid < iv.b) {
            require(result.intervals.size() + pending.size() < kMaxIntervals, "tolerance",
                    "needs more than 200,000 spans along the path: too fine for this sweep");
            pending.push_back({iv.span, mid, iv.b});
            pending.push_back({iv.span, iv.a, mid});
            continue;
        }
        result.intervals.push_back(iv);
        result.pieces.push_back(std::move(piece));
    }
    return result;
}

// The knot multiplicity where two intervals meet: 3 (C2) inside a path span and where the path is C3; 4 (C1)
// where only its third derivative jumps (the trajectories' Q'' holds t'', which holds x'''); 5 (C0) where
// its second derivative or its speed jumps (Q' holds t').
int joint_multiplicity(const Path& path, const Interval3& left, const Interval3& right) {
    if (left.span == right.span) return 3;
    const double t = left.b;
    const PathPoint l = path.at(left.span, t), r = path.at(right.span, t);
    const double speed = std::max(norm(l.d1), norm(r.d1)), scale = speed / path.size();
    auto same = [&](const Vec3& a, const Vec3& b, double order_scale) {
        return norm(a - b) <= 1e-9 * std::max(norm(a), norm(b)) + 1e-12 * order_scale;
    };
    if (!same(l.d1, r.d1, speed) || !same(l.d2, r.d2, speed * scale)) return 5;
    return same(l.d3, r.d3, speed * scale * scale) ? 3 : 4;
}

// The B-spline in v of every trajectory: the Hermite pieces joined as quintic Bezier segments (every joint
// of multiplicity 5), then each joint's knot removed (A5.8) down to the multiplicity its continuity
// allows. The pieces have that continuity by construction, so the removal is unconditional; what it
// changes (rounding) is in the measurement that follows. Knots mapped to [0, 1].
struct Trajectories {
    std::vector<double> knots;
    std::vector<std::vector<Vec3>> points;  // points[i]: trajectory i
    double map(double t) const { return t == t1 ? 1.0 : (t - t0) / (t1 - t0); }
    double t0 = 0, t1 = 1;
};

Trajectories assemble(const Path& path, const Approximation& approx, std::size_t count, bool closed) {
    Trajectories out;
    out.t0 = approx.intervals.front().a;
    out.t1 = approx.intervals.back().b;
    const std::size_t degree = kDegree;
    std::vector<double> bezier_knots(degree + 1, 0.0);
    std::vector<std::pair<double, int>> joints;  // mapped parameter and the multiplicity it keeps
    for (std::size_t n = 1; n < approx.intervals.size(); ++n) {
        const double v = out.map(approx.intervals[n].a);
        bezier_knots.insert(bezier_knots.end(), degree, v);
        joints.push_back({v, joint_multiplicity(path, approx.intervals[n - 1], approx.intervals[n])});
    }
    bezier_knots.insert(bezier_knots.end(), degree + 1, 1.0);
    out.points.assign(count, {});
    for (std::size_t i = 0; i < count; ++i) {
        std::vector<Vec4> pw;
        for (std::size_t n = 0; n < approx.pieces.size(); ++n) {
            const Quintic& b = approx.pieces[n].bezier[i];
            for (std::size_t k = n == 0 ? 0 : 1; k <= degree; ++k) pw.push_back(homogenize(b[k], 1.0));
        }
        if (closed) pw.back() = pw.front();
        std::vector<double> knots = bezier_knots;
        for (const auto& [v, multiplicity] : joints)
            detail::remove_knot(kDegree, knots, pw, v, kDegree - multiplicity, std::numeric_limits<double>::infinity());
        for (const Vec4& q : pw) out.points[i].push_back(weighted_part(q));
        if (i == 0) out.knots = std::move(knots);
    }
    return out;
}

// The largest distance of the assembled trajectories from the exact ones at `samples` points inside each
// interval, per interval.
std::vector<double> measured_errors(const MovingFrame& frame, const Approximation& approx,
                                    const Trajectories& trajectories, const std::vector<Local>& locals, int samples) {
    std::vector<NurbsCurve> curves;
    for (const std::vector<Vec3>& points : trajectories.points) curves.emplace_back(kDegree, trajectories.knots, points);
    std::vector<double> errors;
    for (const Interval3& iv : approx.intervals) {
        double worst = 0;
        for (int k = 1; k <= samples; ++k) {
            const double t = iv.a + (iv.b - iv.a) * k / (samples + 1);
            const FrameData f = frame.at(iv.span, t);
            const double v = trajectories.map(t);
            for (std::size_t i = 0; i < locals.size(); ++i)
                worst = std::max(worst, distance(curves[i].point(v), position(f, locals[i])));
        }
        errors.push_back(worst);
    }
    return errors;
}

// The sweep before the check that it does not meet itself.
Sweep sweep_surfaces_unchecked(const std::vector<NurbsCurve>& sections, const NurbsCurve& path_curve, double tolerance,
                               const char* argument) {
    require(!sections.empty(), argument, "nothing to sweep");
    require_finite(tolerance, "tolerance");
    require(tolerance > 0, "tolerance", "must be greater than 0");
    const Path path(detail::clamped(path_curve));
    check_path(path);
    const bool closed = path_is_closed(path);

    // The start frame: origin x_0, t the tangent, r any normal (the result does not depend on it).
    const PathPoint start = path.at(0, path.start(0));
    const Frame axis_frame = frame_from_axis(start.x, start.d1, "path");
    const Frame start_frame{start.x, axis_frame.x_axis, axis_frame.y_axis, axis_frame.z_axis};
    std::vector<Local> locals;
    Box box;
    box.add(path.curve().control_box());
    for (const NurbsCurve& c : sections)
        for (const Vec4& pw : c.homogeneous_points()) {
            const Vec3 r = project(pw) - start.x;
            locals.push_back({dot(r, start_frame.x_axis), dot(r, start_frame.y_axis), dot(r, start_frame.z_axis)});
            box.add(project(pw));
        }
    require(tolerance >= 1e-12 * box.diagonal(), "tolerance", [&] {
        return "must be at least 1e-12 of the sweep's size (" + number(1e-12 * box.diagonal()) +
               "): below that double precision cannot tell";
    });
    double rho = 0;
    for (const Local& l : locals) rho = std::max(rho, std::sqrt(l.x * l.x + l.y * l.y + l.z * l.z));

    Sweep result;
    result.closed = closed;
    result.start_frame = start_frame;
    if (const std::optional<Line> line = closed ? std::nullopt : as_line(path)) {
        result.method = SweepMethod::extrusion;
        for (const NurbsCurve& c : sections) result.surfaces.push_back(extrude_surface(c, line->displacement));
        result.end_frame = start_frame;
        result.end_frame.origin = start_frame.origin + line->displacement;
        result.construction = Construction::Extrusion{line->displacement, norm(line->displacement)};
        return result;
    }
    if (const std::optional<Arc> arc = as_arc(path)) {
        // The section must stay on the path's side of the axis (the bend check at constant curvature 1/R).
        FrameData f{};
        f.x1 = start.d1;
        f.t1 = unit(arc->centre - start.x) * (norm(start.d1) / arc->radius);
        f.r = start_frame.x_axis;
        f.s = start_frame.y_axis;
        check_bend(f, locals, path.start(0), argument);
        result.method = SweepMethod::revolution;
        for (const NurbsCurve& c : sections)
            result.surfaces.push_back(transposed(revolve_surface(c, arc->centre, arc->axis, arc->angle_deg)));
        const double c = detail::cos_deg(arc->angle_deg), s = detail::sin_deg(arc->angle_deg);
        result.end_frame = Frame{arc->centre + rotated(start.x - arc->centre, arc->axis, c, s),
                                 rotated(start_frame.x_axis, arc->axis, c, s), rotated(start_frame.y_axis, arc->axis, c, s),
                                 rotated(start_frame.z_axis, arc->axis, c, s)};
        result.construction = Construction::Revolution{arc->centre, arc->axis, arc->angle_deg};
        return result;
    }

    if (const std::optional<std::vector<Piece>> pieces = closed ? std::nullopt : as_lines_and_arcs(path)) {
        // Lines and arcs end to end (a sketch's line and tangent arc): the RMF is constant along a line and turns
        // with an arc (about its axis, whichever way the section faces), so the sweep is piece by piece the
        // extrusion or the revolution of the section where the pieces before have carried it, exact.
        std::vector<std::vector<NurbsSurface>> per_section(sections.size());
        std::vector<NurbsCurve> carried = sections;
        Frame frame = start_frame;
        std::vector<double> lengths;
        for (const Piece& piece : *pieces) {
            if (piece.line) {
                const Vec3 d = piece.line->displacement;
                for (std::size_t i = 0; i < carried.size(); ++i) {
                    per_section[i].push_back(extrude_surface(carried[i], d));
                    carried[i] = transformed(carried[i], AffineMap::translation(d));
                }
                frame.origin = frame.origin + d;
                lengths.push_back(norm(d));
                continue;
            }
            const Arc& arc = *piece.arc;
            FrameData f{};  // the bend check at the arc's start, as for a whole arc above
            f.x1 = frame.z_axis;
            f.t1 = unit(arc.centre - frame.origin) / arc.radius;
            f.r = frame.x_axis;
            f.s = frame.y_axis;
            check_bend(f, locals, piece.start, argument);
            const double c = detail::cos_deg(arc.angle_deg), sn = detail::sin_deg(arc.angle_deg);
            const AffineMap turn = AffineMap::rotation(arc.centre, arc.axis, arc.angle_deg);
            for (std::size_t i = 0; i < carried.size(); ++i) {
                per_section[i].push_back(transposed(revolve_surface(carried[i], arc.centre, arc.axis, arc.angle_deg)));
                carried[i] = transformed(carried[i], turn);
            }
            frame = Frame{arc.centre + rotated(frame.origin - arc.centre, arc.axis, c, sn), rotated(frame.x_axis, arc.axis, c, sn),
                          rotated(frame.y_axis, arc.axis, c, sn), rotated(frame.z_axis, arc.axis, c, sn)};
            lengths.push_back(arc.radius * arc.angle_deg * kPi / 180);
        }
        // v over [0, 1] in proportion to the pieces' lengths.
        double total = 0;
        for (double length : lengths) total += length;
        std::vector<double> starts{0.0};
        for (double length : lengths) starts.push_back(starts.back() + length / total);
        starts.back() = 1.0;
        result.method = SweepMethod::lines_and_arcs;
        for (std::vector<NurbsSurface>& surfaces : per_section) result.surfaces.push_back(joined_along_v(std::move(surfaces), starts));
        result.joints.assign(starts.begin() + 1, starts.end() - 1);
        result.end_frame = frame;
        return result;
    }

    // The general case: the frame to a tenth of the tolerance (at the section's reach rho), then the
    // trajectories to the rest.
    double step_angle = 0.5 * kPi / 180;
    std::optional<MovingFrame> frame;
    for (;;) {
        frame.emplace(path, start_frame.x_axis, step_angle, closed);
        if (frame->error() * rho <= 0.1 * tolerance) break;
        step_angle /= 2;
    }
    for (const Reference& s : frame->samples()) check_bend(frame->at(s.span, s.t), locals, s.t, argument);
    check_far_parts(frame->samples(), rho, closed, argument);

    // Pieces from one interval per path span, halved until their estimate (8 points) is below the budget; then
    // the assembled trajectories measured at 24 points per interval, and the intervals still above it halved
    // and everything built again, until the measurement holds.
    const double frame_error = frame->error() * rho;
    const double budget = tolerance - frame_error;
    std::vector<Interval3> intervals;
    for (std::size_t k = 0; k < path.spans(); ++k) intervals.push_back({k, path.start(k), path.end(k)});
    Approximation approx;
    Trajectories trajectories;
    for (;;) {
        approx = approximate(intervals, *frame, locals, budget);
        trajectories = assemble(path, approx, locals.size(), closed);
        const std::vector<double> errors = measured_errors(*frame, approx, trajectories, locals, kVerificationSamples);
        intervals.clear();
        bool refined = false;
        double worst = 0;
        for (std::size_t n = 0; n < errors.size(); ++n) {
            const Interval3& iv = approx.intervals[n];
            const double mid = 0.5 * (iv.a + iv.b);
            if (errors[n] > budget && mid > iv.a && mid < iv.b) {
                intervals.push_back({iv.span, iv.a, mid});
                intervals.push_back({iv.span, mid, iv.b});
                refined = true;
            } else {
                intervals.push_back(iv);
                worst = std::max(worst, errors[n]);
            }
        }
        if (!refined) {
            result.max_error = worst + frame_error;
            break;
        }
    }
    result.method = SweepMethod::approximation;
    require(result.max_error <= tolerance, "tolerance", [&] {
        return "could not be verified: the approximation measured " + number(result.max_error) + " from the sweep";
    });

    std::size_t first = 0;
    for (const NurbsCurve& c : sections) {
        const std::vector<Vec4>& pw = c.homogeneous_points();
        const std::size_t columns = trajectories.points[first].size();
        std::vector<Vec4> net;
        net.reserve(pw.size() * columns);
        for (std::size_t i = 0; i < pw.size(); ++i)
            for (const Vec3& q : trajectories.points[first + i]) net.push_back(homogenize(q, pw[i].w));
        result.surfaces.push_back(
            NurbsSurface::from_homogeneous(c.degree(), kDegree, c.knots(), trajectories.knots, std::move(net), c.is_rational()));
        first += pw.size();
    }
    const FrameData end = frame->at(path.spans() - 1, path.end(path.spans() - 1));
    result.end_frame = closed ? start_frame : Frame{end.x, end.r, end.s, end.t};
    return result;
}

// Never a swept surface that meets itself: the bend and far-parts checks above refuse the usual causes in
// their own words; this certifies the surfaces themselves (self_intersection.hpp), side by side as the
// sections are, closed round where the sections close and along where the path does.
void require_embedded_sweep(const Sweep& sweep, const std::vector<NurbsCurve>& sections, const char* argument) {
    Box box;
    for (const NurbsCurve& c : sections) box.add(c.control_box());
    const bool closed_round = distance(sections.front().start_point(), sections.back().end_point()) <= 1e-9 * box.diagonal();
    detail::require_embedded(
        {sweep.surfaces, closed_round, sweep.closed}, argument, "swept surface",
        [](const detail::SelfIntersection& at) { return " (at path parameter " + number(at.v) + " of [0, 1])"; },
        "a section reaching further into a bend than the bend's radius, or a path that comes back to itself, gives no "
        "valid sweep");
}

}  // namespace

Sweep sweep_surfaces(const std::vector<NurbsCurve>& sections, const NurbsCurve& path_curve, double tolerance,
                     const char* argument) {
    Sweep result = sweep_surfaces_unchecked(sections, path_curve, tolerance, argument);
    require_embedded_sweep(result, sections, argument);
    return result;
}

Solid sweep(const Profile& profile, const NurbsCurve& path, double tolerance) {
    const detail::PlanarProfile planar = detail::analyse_planar_profile(profile);
    const Path probe(detail::clamped(path));
    check_path(probe);
    const Vec3 tangent = unit(probe.at(0, probe.start(0)).d1);
    const double cosine = dot(planar.normal, tangent);
    require(std::abs(cosine) > 1e-9, "profile",
            "lies in a plane containing the path's starting tangent; the profile must cross the path");
    const Profile oriented = cosine > 0 ? profile : profile.reversed();
    const Vec3 normal = cosine > 0 ? planar.normal : -planar.normal;
    const Sweep swept = sweep_surfaces(oriented.pieces(), path, tolerance, "profile");
    if (const auto* turn = swept.construction.get<Construction::Revolution>()) {
        // The profile in a plane through the axis (revolve's first rule, to its tolerance: every control point near
        // the plane through the axis across the profile): the sweep is its revolution. The bend check above keeps
        // the profile off the axis, revolve's other rules.
        const Vec3 across = cross(turn->axis_dir, normal);
        const Vec3 plane_normal = norm(across) > 0.5 ? unit(cross(across, turn->axis_dir)) : Vec3{};
        const bool in_plane = std::ranges::all_of(oriented.pieces(), [&](const NurbsCurve& piece) {
            return std::ranges::all_of(piece.homogeneous_points(), [&](const Vec4& pw) {
                return std::abs(dot(project(pw) - turn->axis_point, plane_normal)) <= oriented.tolerance();
            });
        });
        if (norm(plane_normal) > 0 && in_plane) return revolve(oriented, turn->axis_point, turn->axis_dir, turn->angle_deg);
    }
    if (swept.closed) return detail::tube_solid({swept.surfaces}, std::nullopt);
    const Frame& a = swept.start_frame;
    const Vec3 local{dot(normal, a.x_axis), dot(normal, a.y_axis), dot(normal, a.z_axis)};
    const Vec3 end_normal = swept.end_frame.direction_to_world(local);
    const detail::CapNormals caps{-normal, end_normal / norm(end_normal)};
    if (!swept.joints.empty()) {
        // A face per piece of the path (a line, an arc), as Part's Sweep makes one per path edge: the joints are
        // creases in the surfaces' parameter, which OpenCASCADE would otherwise get as patches.
        detail::TubeBands bands(swept.joints.size() + 1);
        for (const NurbsSurface& surface : swept.surfaces) {
            std::vector<NurbsSurface> parts = split_at_joints_v(surface, swept.joints);
            for (std::size_t b = 0; b < parts.size(); ++b) bands[b].push_back(std::move(parts[b]));
        }
        return detail::tube_solid_in_bands({bands}, caps);
    }
    const Construction record = swept.construction.get<Construction::Extrusion>() ? swept.construction : Construction{};
    return detail::tube_solid({swept.surfaces}, caps, record);
}

}  // namespace ratbez
