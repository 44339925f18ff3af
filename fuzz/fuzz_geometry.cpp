// Fuzz target: curve and surface constructors from raw numbers, then everything that can be asked of
// the result. The first byte picks the object (Bézier curve, Bézier surface, NURBS curve, NURBS surface,
// revolve, extrude); degrees, counts, knots, points and weights follow, decoded by ByteReader. Degrees
// and counts are mostly small (so one input stays fast) and sometimes raw 32-bit values, to check that
// absurd sizes are rejected before anything is allocated.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "harness.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/error.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/surface_grid.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::fuzz {
namespace {

Vec3 decode_point(ByteReader& in) {
    const double x = in.number(), y = in.number(), z = in.number();
    return {x, y, z};
}

// A degree: small almost always, a raw 32-bit value now and then.
int decode_degree(ByteReader& in, int max_small) {
    const std::uint8_t kind = in.byte();
    if (kind == 0xff) return static_cast<int>(in.u32());
    return kind % (max_small + 1);
}

// A parameter: usually inside [a, b], sometimes anything.
double decode_parameter(ByteReader& in, double a, double b) {
    const std::uint8_t kind = in.byte();
    if (kind % 8 == 0) return in.number();
    const double t = static_cast<double>(in.byte()) / 255.0;
    return a + (b - a) * t;
}

// A knot vector of `count` values: non-decreasing steps (zero steps make multiplicities) with the
// ends usually clamped, or raw numbers now and then.
std::vector<double> decode_knots(ByteReader& in, std::size_t count, int degree) {
    std::vector<double> knots;
    knots.reserve(count);
    const std::uint8_t mode = in.byte();
    if (mode % 16 == 0) {
        for (std::size_t i = 0; i < count; ++i) knots.push_back(in.number());
        return knots;
    }
    const bool clamped = (mode & 1) != 0;
    const double scale = (mode & 2) ? in.number() : 1.0;
    double knot = (mode & 4) ? in.number() : 0.0;
    const std::size_t p = static_cast<std::size_t>(std::max(degree, 0));
    for (std::size_t i = 0; i < count; ++i) {
        // Clamped: the first and the last p + 1 knots repeat the end values.
        const bool step = i > 0 && (!clamped || (i > p && i + p < count));
        if (step) knot += scale * static_cast<double>(in.byte() % 4);
        knots.push_back(knot);
    }
    return knots;
}

// A count that is mostly small; 0xff asks for a raw 32-bit one (an absurd size must be rejected).
std::size_t decode_count(ByteReader& in, std::size_t low, std::size_t high) {
    const std::uint8_t kind = in.byte();
    if (kind == 0xff) return in.u32();
    return low + kind % (high - low + 1);
}

// The vectors a constructor is given never exceed what the input can fill, so a raw size is only ever
// a claim (a degree, a row count) that validation must catch, not an allocation the harness makes.
constexpr std::size_t max_vector = 64;

void exercise(const BezierCurve& curve, ByteReader& in) {
    const int queries = in.small(1, 4);
    for (int q = 0; q < queries; ++q) {
        const double u = decode_parameter(in, 0, 1);
        attempt([&] { (void)curve.point(u); });
        attempt([&] { (void)curve.point_de_casteljau(u); });
        attempt([&] { (void)curve.derivatives(u, in.small(0, 6)); });
        attempt([&] { (void)curve.de_casteljau_table(u); });
        attempt([&] {
            const auto [left, right] = curve.split(u);
            (void)left.point(1.0);
            (void)right.point(0.0);
        });
    }
    attempt([&] { (void)curve.elevate().point(0.5); });
    attempt([&] { (void)curve.reversed().point(0.25); });
}

void bezier_curve(ByteReader& in) {
    const std::size_t count = std::min(decode_count(in, 1, 16), max_vector);
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < count; ++i) points.push_back(decode_point(in));
    if (in.flag()) {
        std::vector<double> weights;
        const std::size_t weight_count = in.flag() ? count : std::min<std::size_t>(in.small(0, 16), max_vector);
        for (std::size_t i = 0; i < weight_count; ++i) weights.push_back(in.weight());
        exercise(BezierCurve(points, weights), in);
    } else {
        exercise(BezierCurve(points), in);
    }
}

void exercise(const BezierSurface& surface, ByteReader& in) {
    const int queries = in.small(1, 3);
    for (int q = 0; q < queries; ++q) {
        const double u = decode_parameter(in, 0, 1), v = decode_parameter(in, 0, 1);
        attempt([&] { (void)surface.point(u, v); });
        attempt([&] { (void)surface.point_u_first(u, v); });
        attempt([&] { (void)surface.point_v_first(u, v); });
        attempt([&] { (void)surface.point_one_step(u, v); });
        attempt([&] { (void)surface.derivatives(u, v, in.small(0, 4)); });
        attempt([&] { (void)surface.derivative(u, v, in.small(0, 3), in.small(0, 3)); });
        attempt([&] { (void)surface.normal(u, v); });
        attempt([&] { (void)surface.isocurve_u(u).point(v); });
        attempt([&] { (void)surface.isocurve_v(v).point(u); });
    }
    attempt([&] { (void)NurbsSurface::from_bezier(surface).bezier_patches(); });
}

void bezier_surface(ByteReader& in) {
    const std::size_t rows = std::min(decode_count(in, 1, 6), max_vector);
    const std::size_t columns = std::min(decode_count(in, 1, 6), max_vector / std::max<std::size_t>(rows, 1) + 1);
    std::vector<std::vector<Vec3>> net(rows);
    for (auto& row : net) {
        // A ragged net now and then: the constructor must notice.
        const std::size_t length = in.byte() == 0xfe ? columns + 1 : columns;
        for (std::size_t j = 0; j < length; ++j) row.push_back(decode_point(in));
    }
    if (in.flag()) {
        std::vector<std::vector<double>> weights(in.byte() == 0xfe ? rows + 1 : rows);
        for (auto& row : weights)
            for (std::size_t j = 0; j < columns; ++j) row.push_back(in.weight());
        exercise(BezierSurface(net, weights), in);
    } else {
        exercise(BezierSurface(net), in);
    }
}

NurbsCurve decode_nurbs_curve(ByteReader& in) {
    const int degree = decode_degree(in, 6);
    const std::size_t count = std::min(decode_count(in, 1, 12), max_vector);
    // The knot count is usually right, sometimes off by a little (validation must catch it).
    const std::uint8_t off = in.byte();
    const long long wanted = static_cast<long long>(count) + std::clamp(degree, -1, 1000) + 1 +
                             (off % 16 == 0 ? static_cast<int>(off >> 4) - 8 : 0);
    const std::size_t knot_count = static_cast<std::size_t>(std::clamp<long long>(wanted, 0, max_vector * 2));
    std::vector<double> knots = decode_knots(in, knot_count, std::clamp(degree, -1, 1000));
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < count; ++i) points.push_back(decode_point(in));
    if (in.flag()) {
        std::vector<double> weights;
        for (std::size_t i = 0; i < count; ++i) weights.push_back(in.weight());
        return NurbsCurve(degree, std::move(knots), std::move(points), std::move(weights));
    }
    return NurbsCurve(degree, std::move(knots), std::move(points));
}

void exercise(const NurbsCurve& curve, ByteReader& in) {
    const Interval domain = curve.domain();
    const int queries = in.small(1, 4);
    for (int q = 0; q < queries; ++q) {
        const double u = decode_parameter(in, domain.min, domain.max);
        attempt([&] { (void)curve.point(u); });
        attempt([&] { (void)curve.derivatives(u, in.small(0, 6)); });
        attempt([&] {
            const int times = in.byte() == 0xff ? static_cast<int>(in.u32()) : in.small(0, 4);
            const NurbsCurve refined = curve.insert_knot(u, times);
            (void)refined.point(u);
        });
    }
    attempt([&] {
        for (const BezierCurve& piece : curve.bezier_segments()) (void)piece.point(0.5);
    });
    attempt([&] { (void)curve.reversed().start_point(); });
    attempt([&] {
        const double a = in.number(), b = in.number();
        (void)curve.reparameterized(a, b).end_point();
    });
}

NurbsSurface decode_nurbs_surface(ByteReader& in) {
    const int degree_u = decode_degree(in, 4), degree_v = decode_degree(in, 4);
    const std::size_t rows = std::min(decode_count(in, 1, 7), max_vector);
    const std::size_t columns = std::min(decode_count(in, 1, 7), max_vector / std::max<std::size_t>(rows, 1) + 1);
    const auto knot_count = [](std::size_t n, int p) {
        return static_cast<std::size_t>(std::clamp<long long>(static_cast<long long>(n) + std::clamp(p, -1, 1000) + 1, 0,
                                                              max_vector * 2));
    };
    std::vector<double> knots_u = decode_knots(in, knot_count(rows, degree_u), std::clamp(degree_u, -1, 1000));
    std::vector<double> knots_v = decode_knots(in, knot_count(columns, degree_v), std::clamp(degree_v, -1, 1000));
    std::vector<std::vector<Vec3>> net(rows);
    for (auto& row : net)
        for (std::size_t j = 0; j < columns; ++j) row.push_back(decode_point(in));
    if (in.flag()) {
        std::vector<std::vector<double>> weights(rows);
        for (auto& row : weights)
            for (std::size_t j = 0; j < columns; ++j) row.push_back(in.weight());
        return NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(net), std::move(weights));
    }
    return NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(net));
}

void exercise(const NurbsSurface& surface, ByteReader& in) {
    const Interval du = surface.domain_u(), dv = surface.domain_v();
    const int queries = in.small(1, 3);
    for (int q = 0; q < queries; ++q) {
        const double u = decode_parameter(in, du.min, du.max), v = decode_parameter(in, dv.min, dv.max);
        attempt([&] { (void)surface.point(u, v); });
        attempt([&] { (void)surface.derivatives(u, v, in.small(0, 3)); });
        attempt([&] { (void)surface.normal(u, v); });
        attempt([&] { (void)surface.isocurve_u(u).point(v); });
        attempt([&] { (void)surface.isocurve_v(v).point(u); });
        attempt([&] { (void)surface.insert_knot_u(u, in.small(0, 3)).point(u, v); });
        attempt([&] { (void)surface.insert_knot_v(v, in.small(0, 3)).point(u, v); });
    }
    attempt([&] {
        for (const auto& row : surface.bezier_patches())
            for (const BezierSurface& patch : row) (void)patch.point(0.5, 0.5);
    });
    attempt([&] {
        const std::size_t nu = in.small(0, 6), nv = in.small(0, 6);
        std::vector<double> us, vs;
        for (std::size_t i = 0; i < nu; ++i) us.push_back(decode_parameter(in, du.min, du.max));
        for (std::size_t j = 0; j < nv; ++j) vs.push_back(decode_parameter(in, dv.min, dv.max));
        std::sort(us.begin(), us.end());
        std::sort(vs.begin(), vs.end());
        (void)evaluate_grid(surface, us, vs, static_cast<GridOutput>(in.small(0, 2)));
    });
}

Profile decode_profile(ByteReader& in) {
    const int pieces = in.small(1, 4);
    std::vector<NurbsCurve> curves;
    for (int k = 0; k < pieces; ++k) {
        if (in.flag()) {
            // A Bézier piece, rational or not.
            const std::size_t count = static_cast<std::size_t>(in.small(2, 5));
            std::vector<Vec3> points;
            for (std::size_t i = 0; i < count; ++i) points.push_back(decode_point(in));
            if (k > 0 && in.flag()) points.front() = curves.back().end_point();  // joined, usually
            std::vector<double> weights;
            for (std::size_t i = 0; i < count; ++i) weights.push_back(in.flag() ? 1.0 : in.weight());
            curves.push_back(NurbsCurve::from_bezier(BezierCurve(points, weights)));
        } else {
            curves.push_back(decode_nurbs_curve(in));
        }
    }
    if (in.flag() && curves.size() > 1) {
        // Close it: the last piece ends where the first starts (by a line, the usual way).
        const Vec3 a = curves.back().end_point(), b = curves.front().start_point();
        curves.push_back(NurbsCurve::from_bezier(BezierCurve({a, b})));
    }
    return Profile(std::move(curves));
}

// Tessellate what was built, coarsely (so the input stays fast) with a small budget that must reject,
// not allocate; the mesh must be closed.
void tessellate_coarsely(const Solid& solid, ByteReader& in) {
    (void)solid.volume();
    const double size = solid.bounding_box().diagonal();
    if (!(size > 0) || !std::isfinite(size)) return;
    TessellationOptions options;
    options.tolerance = size / (20.0 + in.byte());
    options.max_triangles = 5'000;
    const Mesh mesh = tessellate(solid, options);
    if (!mesh.is_closed()) invariant_failed("fuzz_geometry", "tessellation is not closed");
}

void revolve_case(ByteReader& in) {
    const Profile profile = decode_profile(in);
    const Vec3 axis_point = in.flag() ? decode_point(in) : Vec3{};
    const Vec3 axis_dir = in.flag() ? decode_point(in) : Vec3{0, 0, 1};
    const double angle = in.flag() ? 360.0 : in.number();
    for (const NurbsCurve& piece : profile.pieces()) {
        attempt([&] {
            const NurbsSurface surface = revolve_surface(piece, axis_point, axis_dir, angle);
            (void)surface.normal(surface.domain_u().min, surface.domain_v().max);
        });
    }
    const Solid solid = revolve(profile, axis_point, axis_dir, angle);
    tessellate_coarsely(solid, in);
}

void extrude_case(ByteReader& in) {
    const Profile profile = decode_profile(in);
    const Vec3 direction = in.flag() ? decode_point(in) : Vec3{0, 0, 1};
    const double distance = in.number();
    for (const NurbsCurve& piece : profile.pieces())
        attempt([&] { (void)extrude_surface(piece, direction * distance).point(piece.domain().min, 0.5); });
    const Solid solid = extrude(profile, direction, distance);
    tessellate_coarsely(solid, in);
}

}  // namespace

void run_geometry(const std::uint8_t* data, std::size_t size) {
    ByteReader in(data, size);
    switch (in.byte() % 6) {
        case 0: bezier_curve(in); break;
        case 1: bezier_surface(in); break;
        case 2: {
            const NurbsCurve curve = decode_nurbs_curve(in);
            exercise(curve, in);
            break;
        }
        case 3: {
            const NurbsSurface surface = decode_nurbs_surface(in);
            exercise(surface, in);
            break;
        }
        case 4: revolve_case(in); break;
        default: extrude_case(in); break;
    }
}

}  // namespace ratbez::fuzz

#ifndef RATBEZ_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // A rejected input (ratbez::Error) is the one allowed outcome besides success.
    ratbez::fuzz::attempt([&] { ratbez::fuzz::run_geometry(data, size); });
    return 0;
}
#endif
