// The global nearest point of curves and surfaces (closest_point.hpp), against references that do not
// share its search: the distance in closed form where the shape has one (circle arc, sphere, torus, cone,
// a plane patch, and a full surface of revolution, whose distance is the distance to its profile in the
// (radius, height) half-plane), else a brute-force dense search (a dense polyline or grid, then
// golden-section or compass search from every sample nearer than its neighbours). On random points near
// and far from each shape the distance must agree with the reference to 1e-9 of the shape's size and
// never exceed it beyond rounding (a larger value is a missed foot). Every foot must be a point of the
// shape at its returned parameters.
//
// Points per shape: RATBEZ_CLOSEST_POINT_CASES, default 10,000 (300 under AddressSanitizer); all pass at
// 100,000.

#include "ratbez/closest_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "analysis/point_inversion.hpp"
#include "geometry/surface_evaluator.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "test_support.hpp"

namespace ratbez {
namespace {

// Fewer points under AddressSanitizer, whose checks make every evaluation several times dearer.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
constexpr bool kSanitized = __has_feature(address_sanitizer);
#else
constexpr bool kSanitized = false;
#endif

int cases() {
    const char* text = std::getenv("RATBEZ_CLOSEST_POINT_CASES");
    return text != nullptr && *text != '\0' ? std::max(1, std::atoi(text)) : kSanitized ? 300 : 10000;
}

using Rng = std::mt19937_64;
double uniform(Rng& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
Vec3 uniform_in(Rng& rng, const Box& box) {
    return {uniform(rng, box.min.x, box.max.x), uniform(rng, box.min.y, box.max.y), uniform(rng, box.min.z, box.max.z)};
}
Vec3 random_direction(Rng& rng) {
    for (;;) {
        const Vec3 d{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
        const double length = norm(d);
        if (length > 0.1 && length <= 1) return d / length;
    }
}
Box grown(Box box, double margin) {
    box.add(box.min - Vec3{margin, margin, margin});
    box.add(box.max + Vec3{margin, margin, margin});
    return box;
}

// ---- references

// The distance from p to a curve by brute force: a polyline through curve points no more than `spacing`
// apart (each knot span cut into 64 and each piece bisected until its ends are that close); every vertex
// nearer than its neighbours, within two spacings of the nearest vertex, is refined by golden-section
// search over its two neighbouring parameter intervals.
class CurveReference {
public:
    CurveReference(const NurbsCurve& curve, double spacing) : curve_(curve), spacing_(spacing) {
        const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
        add(breaks.front());
        for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
            for (int i = 0; i < 64; ++i)
                refine(breaks[k] + (breaks[k + 1] - breaks[k]) * i / 64.0,
                       i == 63 ? breaks[k + 1] : breaks[k] + (breaks[k + 1] - breaks[k]) * (i + 1) / 64.0, 0);
    }

    double distance_to(const Vec3& p) const {
        const std::size_t n = t_.size();
        std::vector<double> d(n);
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < n; ++k) nearest = std::min(nearest, d[k] = distance(points_[k], p));
        double best = nearest;
        for (std::size_t k = 0; k < n; ++k) {
            if (d[k] > nearest + 2 * spacing_ || (k > 0 && d[k - 1] < d[k]) || (k + 1 < n && d[k + 1] < d[k])) continue;
            best = std::min(best, golden_section(p, t_[k == 0 ? 0 : k - 1], t_[k + 1 == n ? k : k + 1]));
        }
        return best;
    }

private:
    void add(double t) {
        t_.push_back(t);
        points_.push_back(curve_.point(t));
    }
    void refine(double a, double b, int depth) {  // adds the points after a up to b
        if (depth < 30 && distance(curve_.point(a), curve_.point(b)) > spacing_) {
            refine(a, 0.5 * (a + b), depth + 1);
            refine(0.5 * (a + b), b, depth + 1);
        } else {
            add(b);
        }
    }
    double golden_section(const Vec3& p, double a, double b) const {
        const double ratio = (std::sqrt(5.0) - 1) / 2;
        auto f = [&](double t) { return distance(curve_.point(t), p); };
        double c = b - ratio * (b - a), e = a + ratio * (b - a), fc = f(c), fe = f(e);
        double best = std::min({f(a), f(b), fc, fe});
        for (int i = 0; i < 48; ++i) {
            if (fc < fe) b = e, e = c, fe = fc, c = b - ratio * (b - a), fc = f(c);
            else a = c, c = e, fc = fe, e = a + ratio * (b - a), fe = f(e);
            best = std::min({best, fc, fe});
        }
        return best;
    }
    const NurbsCurve& curve_;
    double spacing_;
    std::vector<double> t_;
    std::vector<Vec3> points_;
};

// The distance from p to a bilinear patch by brute force: a 41 x 41 grid of its points, then compass
// search (eight directions, the step halved down to 1e-10) from every grid point nearer than its
// neighbours within two grid spacings of the nearest. The patch is evaluated in closed form here.
class BilinearReference {
public:
    explicit BilinearReference(const std::array<Vec3, 4>& corners) : c_(corners) {
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j) grid_.push_back(at(static_cast<double>(i) / (kGrid - 1), static_cast<double>(j) / (kGrid - 1)));
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j) {
                if (i + 1 < kGrid) spacing_ = std::max(spacing_, distance(grid_[index(i, j)], grid_[index(i + 1, j)]));
                if (j + 1 < kGrid) spacing_ = std::max(spacing_, distance(grid_[index(i, j)], grid_[index(i, j + 1)]));
            }
    }
    Vec3 at(double u, double v) const {
        return (1 - u) * (1 - v) * c_[0] + u * (1 - v) * c_[1] + u * v * c_[2] + (1 - u) * v * c_[3];
    }
    double distance_to(const Vec3& p) const {
        std::vector<double> d(grid_.size());
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < grid_.size(); ++k) nearest = std::min(nearest, d[k] = distance(grid_[k], p));
        double best = nearest;
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j) {
                const double dk = d[index(i, j)];
                if (dk > nearest + 2 * spacing_) continue;
                if ((i > 0 && d[index(i - 1, j)] < dk) || (i + 1 < kGrid && d[index(i + 1, j)] < dk) ||
                    (j > 0 && d[index(i, j - 1)] < dk) || (j + 1 < kGrid && d[index(i, j + 1)] < dk))
                    continue;
                best = std::min(best, compass(p, static_cast<double>(i) / (kGrid - 1), static_cast<double>(j) / (kGrid - 1), dk));
            }
        return best;
    }

private:
    static constexpr int kGrid = 41;
    static std::size_t index(int i, int j) { return static_cast<std::size_t>(i * kGrid + j); }
    double compass(const Vec3& p, double u, double v, double value) const {
        for (double h = 1.0 / (kGrid - 1); h > 1e-10;) {
            bool moved = false;
            for (const auto& [du, dv] : std::array<std::array<double, 2>, 8>{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}}) {
                const double nu = std::clamp(u + h * du, 0.0, 1.0), nv = std::clamp(v + h * dv, 0.0, 1.0);
                const double d = distance(at(nu, nv), p);
                if (d < value) u = nu, v = nv, value = d, moved = true;
            }
            if (!moved) h *= 0.5;
        }
        return value;
    }
    std::array<Vec3, 4> c_;
    std::vector<Vec3> grid_;
    double spacing_ = 0;
};

// The point p as (radius, 0, height) about the z axis: the half-plane of a profile revolved about it.
Vec3 to_profile_plane(const Vec3& p, const Vec3& axis_point = {}) {
    const Vec3 d = p - axis_point;
    return {std::hypot(d.x, d.y), 0, d.z};
}

// ---- the comparison

struct Tally {
    int missed = 0, inaccurate = 0, off_shape = 0;
    double worst_excess = 0, worst_gap = 0;
    std::string first;
};

// One point: `foot_distance` from closest_point, `reference` the reference distance, `on_shape_gap` how
// far the returned point lies from the shape's point at the returned parameters.
void compare(Tally& tally, const Vec3& p, double foot_distance, double reference, double on_shape_gap, double size) {
    const double excess = foot_distance - reference;
    tally.worst_excess = std::max(tally.worst_excess, excess / size);
    tally.worst_gap = std::max(tally.worst_gap, std::abs(excess) / size);
    auto note = [&](const char* what) {
        if (tally.first.empty())
            tally.first = std::string(what) + " at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
                          std::to_string(p.z) + "): " + std::to_string(foot_distance) + " vs reference " +
                          std::to_string(reference);
    };
    if (excess > 1e-12 * size) ++tally.missed, note("larger than the reference");
    if (std::abs(excess) > 1e-9 * size) ++tally.inaccurate, note("off the reference by more than 1e-9");
    if (on_shape_gap > 1e-12 * size) ++tally.off_shape, note("the point is not the shape's point at its parameters");
}

void expect_clean(const Tally& tally, const std::string& shape) {
    EXPECT_EQ(tally.missed, 0) << shape << ": " << tally.first;
    EXPECT_EQ(tally.inaccurate, 0) << shape << ": " << tally.first;
    EXPECT_EQ(tally.off_shape, 0) << shape << ": " << tally.first;
    ::testing::Test::RecordProperty(shape + "_worst_excess_over_size", std::to_string(tally.worst_excess));
}

// Points for a shape: half near it (a point of it at random parameters, moved up to 10% of its size in a
// random direction), half anywhere in its box grown by half its size on every side.
template <class PointAt>
std::vector<Vec3> random_points(Rng& rng, int count, const Box& box, PointAt&& point_at) {
    const double size = box.diagonal();
    std::vector<Vec3> points;
    for (int k = 0; k < count; ++k) {
        if (k % 2 == 0) points.push_back(point_at(rng) + random_direction(rng) * uniform(rng, 0, 0.1 * size));
        else points.push_back(uniform_in(rng, grown(box, 0.5 * size)));
    }
    return points;
}

void check_curve(const std::string& name, const NurbsCurve& curve, const std::function<double(const Vec3&)>& reference,
                 const std::vector<Vec3>& points) {
    const CurveProjector projector(curve);
    const double size = curve.control_box().diagonal();
    const Interval domain = curve.domain();
    Tally tally;
    for (const Vec3& p : points) {
        const CurveFoot foot = projector.closest_point(p);
        ASSERT_TRUE(domain.contains(foot.u)) << name;
        ASSERT_DOUBLE_EQ(foot.distance, distance(foot.point, p)) << name;
        compare(tally, p, foot.distance, reference(p), distance(foot.point, curve.point(foot.u)), size);
    }
    expect_clean(tally, name);
}

void check_surface(const std::string& name, const NurbsSurface& surface, const std::function<double(const Vec3&)>& reference,
                   const std::vector<Vec3>& points) {
    const SurfaceProjector projector(surface);
    const double size = surface.control_box().diagonal();
    Tally tally;
    for (const Vec3& p : points) {
        const SurfaceFoot foot = projector.closest_point(p);
        ASSERT_TRUE(surface.domain_u().contains(foot.u) && surface.domain_v().contains(foot.v)) << name;
        ASSERT_DOUBLE_EQ(foot.distance, distance(foot.point, p)) << name;
        compare(tally, p, foot.distance, reference(p), distance(foot.point, surface.point(foot.u, foot.v)), size);
    }
    expect_clean(tally, name);
}

Vec3 curve_point(Rng& rng, const NurbsCurve& curve) {
    const Interval d = curve.domain();
    return curve.point(uniform(rng, d.min, d.max));
}
Vec3 surface_point(Rng& rng, const NurbsSurface& s) {
    return s.point(uniform(rng, s.domain_u().min, s.domain_u().max), uniform(rng, s.domain_v().min, s.domain_v().max));
}

// A rational cubic from the z axis out and back to it, in the x-z plane (x >= 0): revolved, one face with
// a pole at each end.
BezierCurve rational_profile() {
    return BezierCurve({{0, 0, 0}, {1.6, 0, 0.2}, {1.1, 0, 1.7}, {0, 0, 2}}, {1.0, 0.6, 1.8, 1.0});
}

const Face& surface_face(const Solid& solid) {
    for (const Face& face : solid.faces())
        if (face.kind() == Face::Kind::surface) return face;
    fail("test", "no surface face");
}

// ---- curves

TEST(ClosestPoint, CircleArcAgreesWithClosedForm) {
    const double radius = 2.0, start = 20.0, end = 290.0;
    const NurbsCurve curve = arc(radius, start, end);
    const Vec3 first = curve.start_point(), last = curve.end_point();
    auto exact = [&](const Vec3& p) {
        // Inside the arc's angular range the nearest point is the radial one; outside it, an end.
        double angle = std::atan2(p.y, p.x) * 180 / std::numbers::pi;
        if (angle < 0) angle += 360;
        if (angle >= start && angle <= end) return std::hypot(std::hypot(p.x, p.y) - radius, p.z);
        return std::min(distance(p, first), distance(p, last));
    };
    Rng rng(101);
    check_curve("circle arc", curve, exact, random_points(rng, cases(), curve.control_box(), [&](Rng& r) { return curve_point(r, curve); }));
}

TEST(ClosestPoint, HighWeightRationalCubicAgreesWithBruteForce) {
    // Weights 60 and 0.02: the cubic runs most of its length within a few percent of its parameters.
    const NurbsCurve curve = NurbsCurve::from_bezier(
        BezierCurve({{0, 0, 0}, {1, 2, 0.5}, {3, -1, 1}, {4, 1, 0}}, {1, 60, 0.02, 1}));
    const CurveReference reference(curve, 2e-3 * curve.control_box().diagonal());
    Rng rng(102);
    check_curve("high-weight rational cubic", curve, [&](const Vec3& p) { return reference.distance_to(p); },
                random_points(rng, cases(), curve.control_box(), [&](Rng& r) { return curve_point(r, curve); }));
}

TEST(ClosestPoint, MultiSpanNurbsCurveAgreesWithBruteForce) {
    const NurbsCurve curve(3, {0, 0, 0, 0, 0.1, 0.35, 0.5, 0.8, 1, 1, 1, 1},
                           {{0, 0, 0}, {1, 1.5, 0.2}, {2, -0.5, 0.8}, {3, 1, -0.4}, {3.5, 2.5, 0}, {2.5, 3, 1}, {1, 2.5, 0.3}, {0.5, 3.5, -0.5}},
                           {1, 0.5, 2, 1, 3, 0.7, 1, 1});
    const CurveReference reference(curve, 2e-3 * curve.control_box().diagonal());
    Rng rng(103);
    check_curve("multi-span NURBS curve", curve, [&](const Vec3& p) { return reference.distance_to(p); },
                random_points(rng, cases(), curve.control_box(), [&](Rng& r) { return curve_point(r, curve); }));
}

// ---- surfaces

TEST(ClosestPoint, SphereAgreesWithClosedForm) {
    const Vec3 center{0.2, -0.1, 0.3};
    const double radius = 1.5;
    const Solid solid = sphere(radius, center);
    const NurbsSurface& s = solid.faces().front().surface();
    Rng rng(201);
    check_surface("sphere", s, [&](const Vec3& p) { return std::abs(distance(p, center) - radius); },
                  random_points(rng, cases(), s.control_box(), [&](Rng& r) { return surface_point(r, s); }));
}

TEST(ClosestPoint, TorusAgreesWithClosedForm) {
    const Vec3 center{0.5, 0.2, -0.3};
    const double major = 2.0, minor = 0.6;
    const Solid solid = torus(major, minor, center);
    const NurbsSurface& s = solid.faces().front().surface();
    auto exact = [&](const Vec3& p) {
        const Vec3 q = to_profile_plane(p, center);
        return std::abs(std::hypot(q.x - major, q.z) - minor);
    };
    Rng rng(202);
    check_surface("torus", s, exact, random_points(rng, cases(), s.control_box(), [&](Rng& r) { return surface_point(r, s); }));
}

// The rational profile revolved a full turn about z. The distance to the surface is the distance from
// (radius, height) to the profile in its half-plane, found by the brute-force curve reference.
struct RevolvedProfile {
    NurbsCurve profile = NurbsCurve::from_bezier(rational_profile());
    Solid solid = revolve(Profile::from_beziers({rational_profile()}));
    CurveReference reference{profile, 2e-3 * profile.control_box().diagonal()};

    const NurbsSurface& surface() const { return surface_face(solid).surface(); }
    double distance_to(const Vec3& p) const { return reference.distance_to(to_profile_plane(p)); }
};

// Points uniform in the cubes of half-width `half_width` about `centers`, taken in turn.
std::vector<Vec3> points_around(Rng& rng, const std::vector<Vec3>& centers, double half_width) {
    std::vector<Vec3> points;
    for (int k = 0; k < cases(); ++k)
        points.push_back(centers[static_cast<std::size_t>(k) % centers.size()] +
                         Vec3{uniform(rng, -half_width, half_width), uniform(rng, -half_width, half_width),
                              uniform(rng, -half_width, half_width)});
    return points;
}

TEST(ClosestPoint, RevolvedRationalProfileAgreesWithItsProfile) {
    const RevolvedProfile shape;
    const NurbsSurface& s = shape.surface();
    Rng rng(203);
    check_surface("revolved rational profile", s, [&](const Vec3& p) { return shape.distance_to(p); },
                  random_points(rng, cases(), s.control_box(), [&](Rng& r) { return surface_point(r, s); }));
}

TEST(ClosestPoint, PoleRegionsOfARevolvedProfileAgreeWithItsProfile) {
    // Points crowded around the two poles (the profile's ends on the axis), where S_u vanishes.
    const RevolvedProfile shape;
    Rng rng(204);
    check_surface("revolved profile's poles", shape.surface(), [&](const Vec3& p) { return shape.distance_to(p); },
                  points_around(rng, {{0, 0, 0}, {0, 0, 2}}, 0.1));
}

TEST(ClosestPoint, ConeApexRegionAgreesWithClosedForm) {
    // The lateral face of a cone from radius 1 at z = 0 to its apex at z = 1.5: in the (radius, height)
    // half-plane the segment from (1, 0) to (0, 1.5).
    const Solid solid = cone(1.0, 0.0, 1.5);
    const NurbsSurface& s = surface_face(solid).surface();
    auto exact = [](const Vec3& p) {
        const Vec3 q = to_profile_plane(p), a{1, 0, 0}, b{0, 0, 1.5};
        const double t = std::clamp(dot(q - a, b - a) / dot(b - a, b - a), 0.0, 1.0);
        return distance(q, a + (b - a) * t);
    };
    Rng rng(205);
    check_surface("cone apex", s, exact, points_around(rng, {{0, 0, 1.5}}, 0.3));
}

TEST(ClosestPoint, TwistedBilinearPatchAgreesWithBruteForce) {
    const std::array<Vec3, 4> corners{Vec3{0, 0, 0}, Vec3{2, 0, 0.3}, Vec3{2.2, 1.5, 1.4}, Vec3{-0.1, 1.2, -0.2}};
    const NurbsSurface s(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {{corners[0], corners[3]}, {corners[1], corners[2]}});
    const BilinearReference reference(corners);
    Rng rng(206);
    check_surface("bilinear patch", s, [&](const Vec3& p) { return reference.distance_to(p); },
                  random_points(rng, cases(), s.control_box(), [&](Rng& r) { return surface_point(r, s); }));
}

TEST(ClosestPoint, PlanarPatchAgreesWithClosedForm) {
    // A bicubic patch over the rectangle [0, 2] x [0, 1] of the plane z = 0.5 (control abscissae rising, so
    // its boundary is the rectangle's, parameterised unevenly), turned about a skew axis.
    const std::array<double, 4> xs{0, 0.2, 1.5, 2}, ys{0, 0.6, 0.7, 1};
    const Vec3 axis = Vec3{1, 2, 2} / 3.0;
    const double turn = 0.7;
    auto rotate = [&](const Vec3& p, double angle) {  // Rodrigues' rotation about `axis`
        return p * std::cos(angle) + cross(axis, p) * std::sin(angle) + axis * (dot(axis, p) * (1 - std::cos(angle)));
    };
    std::vector<std::vector<Vec3>> net(4, std::vector<Vec3>(4));
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = 0; j < 4; ++j) net[i][j] = rotate({xs[i], ys[j], 0.5}, turn);
    const NurbsSurface s(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, net);
    auto exact = [&](const Vec3& p) {
        const Vec3 q = rotate(p, -turn);
        return std::hypot(std::hypot(q.x - std::clamp(q.x, 0.0, 2.0), q.y - std::clamp(q.y, 0.0, 1.0)), q.z - 0.5);
    };
    Rng rng(207);
    check_surface("planar patch", s, exact, random_points(rng, cases(), s.control_box(), [&](Rng& r) { return surface_point(r, s); }));
}

// ---- the one-point functions and bad input

TEST(ClosestPoint, OnePointFunctionsMatchTheProjectors) {
    const NurbsCurve curve = arc(1.0, 0, 200);
    const Solid solid = torus(2.0, 0.5);
    const NurbsSurface& s = solid.faces().front().surface();
    for (const Vec3& p : {Vec3{0.3, 2, 1}, Vec3{-3, 0.1, 0.2}, Vec3{0, 0, 0}}) {
        const CurveFoot a = closest_point(curve, p), b = CurveProjector(curve).closest_point(p);
        EXPECT_EQ(a.u, b.u);
        EXPECT_EQ(a.distance, b.distance);
        const SurfaceFoot c = closest_point(s, p), d = SurfaceProjector(s).closest_point(p);
        EXPECT_EQ(c.u, d.u);
        EXPECT_EQ(c.v, d.v);
        EXPECT_EQ(c.distance, d.distance);
    }
    // A point on the surface is its own foot.
    const Vec3 on = s.point(0.3, 0.7);
    EXPECT_LE(closest_point(s, on).distance, 1e-14);
}

TEST(ClosestPoint, InteriorMinimumBesideASideMinimumIsFound) {
    // A random rational bicubic (found by the Python bindings' brute-force test): along v = 0 the distance
    // has a minimum 1.639817 at u = 0.730; the surface's 1.639207 lies at (0.676, 0.0196), between the
    // seeds and nearer the side than they are to each other. Newton from the side's minimum started again
    // half a seed spacing inside finds it.
    const std::vector<std::vector<Vec3>> net{
        {{0, 0, 0.9457339541686962}, {0, 1, 0.5775223352115382}, {0, 2, 0.3498804807842337}, {0, 3, 0.24780616590787874}},
        {{1, 0, -0.3960270929177625}, {1, 1, -0.7036829851535342}, {1, 2, -0.5415005736583696}, {1, 3, 0.7278916046211141}},
        {{2, 0, 0.5273858345754241}, {2, 1, -0.9401550745810596}, {2, 2, 0.990806277275343}, {2, 3, -0.2665574493126992}},
        {{3, 0, -0.25690244415244856}, {3, 1, 0.6400032090328192}, {3, 2, 0.917597147394742}, {3, 3, -0.6010585986442194}}};
    const std::vector<std::vector<double>> weights{{0.8400152707822686, 0.6228871802734832, 0.7800937933811956, 1.0370707001185595},
                                                   {0.5033586351802741, 1.9587442270341324, 1.950952081074143, 0.8761098175096202},
                                                   {0.7311201145676083, 1.1332411523104968, 0.6784763897158019, 0.994470309851981},
                                                   {1.6699168585729607, 1.3255391607598828, 1.22614763636592, 1.7313994507125143}};
    const NurbsSurface s = NurbsSurface::from_bezier(BezierSurface(net, weights));
    const SurfaceFoot foot = closest_point(s, {2.060019527124753, -0.5474279130113626, -1.4960269175145453});
    EXPECT_NEAR(foot.distance, 1.639206996, 1e-9);
    EXPECT_NEAR(foot.u, 0.67614, 1e-5);
    EXPECT_NEAR(foot.v, 0.0196451, 1e-6);
    // The same patch: the foot on the side u = 1 at v = 0.0306 (1.2487788, by a search of 400,000 points
    // along that side) next to the side v = 0's minimum 1.2494945 at u = 0.957 that the seeds lead to; the
    // sides are now searched as curves.
    const SurfaceFoot side = closest_point(s, {3.54158989101568, -0.6597204349098514, 0.6612147066479315});
    EXPECT_NEAR(side.distance, 1.248778778, 1e-9);
    EXPECT_EQ(side.u, 1.0);
    EXPECT_NEAR(side.v, 0.030579, 1e-6);
}

TEST(ClosestPoint, NewtonAlongASideConverges) {
    // Along a side Newton's matrix across it may be indefinite (a saddle across the side) while the
    // distance along it is convex: the 1D Newton step must be taken there, not Gauss-Newton's, which was
    // twice too long on this random rational bicubic and oscillated about the side's minimum (1.626612 at
    // u = 0.6243) for all 50 iterations, stopping at 1.627571 from (0.6, 0).
    const std::vector<std::vector<Vec3>> net{
        {{0, 0, 0.39621505304600957}, {0, 1, -0.042314407488069694}, {0, 2, 0.7755784375740211}, {0, 3, 0.07053351902728644}},
        {{1, 0, -0.3118698979947687}, {1, 1, -0.037432463335092425}, {1, 2, -0.40289959102199346}, {1, 3, 0.16817663628051194}},
        {{2, 0, -0.6249976084792574}, {2, 1, 0.9810396056870825}, {2, 2, -0.05741777451382446}, {2, 3, 0.883198602278439}},
        {{3, 0, 0.1858430633002346}, {3, 1, 0.39197223030938555}, {3, 2, -0.39748948798618144}, {3, 3, -0.46906038763522506}}};
    const std::vector<std::vector<double>> weights{{0.5208309079495963, 0.6107798396780195, 1.5845935782889116, 1.0401372374519497},
                                                   {0.7295649335417153, 0.9279732888071782, 1.6062393196999112, 1.7719839696739628},
                                                   {0.9431753722297034, 1.5164096345477114, 1.393515981132869, 1.1794038184037126},
                                                   {1.0335262531319866, 1.8579359571366643, 1.0833768759191604, 1.691637749774323}};
    const NurbsSurface s = NurbsSurface::from_bezier(BezierSurface(net, weights));
    const Vec3 p{2.2529312067051324, -0.01605677095827729, -1.9023027710843725};
    double reference = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 100000; ++i) reference = std::min(reference, distance(s.point(i / 100000.0, 0.0), p));
    const detail::SurfaceEvaluator evaluator(s);
    const detail::ParameterFoot foot =
        detail::newton_foot_on_surface(evaluator, p, {{0, 1}, {0, 1}}, 0.6, 0.0, {.max_iterations = 50, .at_rounding = true});
    EXPECT_EQ(foot.v, 0.0);
    EXPECT_NEAR(foot.distance, reference, 1e-9);
    EXPECT_NEAR(closest_point(s, p).distance, reference, 1e-9);
}

TEST(ClosestPoint, RejectsNonFinitePoints) {
    const NurbsCurve curve = arc(1.0, 0, 90);
    const Solid solid = sphere(1.0);
    const NurbsSurface& s = solid.faces().front().surface();
    for (const Vec3& p : {Vec3{test::nan_value, 0, 0}, Vec3{0, test::inf_value, 0}, Vec3{0, 0, -test::inf_value}}) {
        EXPECT_TRUE(test::starts_with(test::error_message([&] { closest_point(curve, p); }), "point: "));
        EXPECT_TRUE(test::starts_with(test::error_message([&] { closest_point(s, p); }), "point: "));
        EXPECT_TRUE(test::starts_with(test::error_message([&] { SurfaceProjector(s).closest_point(p); }), "point: "));
    }
}

}  // namespace
}  // namespace ratbez
