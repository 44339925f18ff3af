#pragma once
// Helpers shared by the primitive, revolve, extrude, B-rep and property tests: seeded random input,
// rigid motions, and the per-solid invariants every shape must satisfy (closure, Euler characteristic,
// outward normals).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>

#include "ratbez/brep.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"
#include "ratbez/vec.hpp"
#include "test_support.hpp"

namespace ratbez::test {

inline constexpr double pi = std::numbers::pi;

inline std::mt19937_64& rng() {
    static std::mt19937_64 engine(20240611);
    return engine;
}
inline double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng()); }
inline Vec3 random_point(double extent) { return {uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)}; }
inline Vec3 random_unit() {
    for (;;) {
        const Vec3 v = random_point(1.0);
        const double n = norm(v);
        if (n > 0.1 && n <= 1.0) return v / n;
    }
}

// Rotation of p about the line (origin, unit axis) by `radians` (Rodrigues).
inline Vec3 rotate_about(const Vec3& p, const Vec3& origin, const Vec3& axis, double radians) {
    const Vec3 r = p - origin;
    const double c = std::cos(radians), s = std::sin(radians);
    return origin + r * c + cross(axis, r) * s + axis * (dot(axis, r) * (1 - c));
}

// Points (u, v) spread over a face's whole parameter rectangle.
inline std::pair<double, double> random_parameter(const Face& face) {
    const Interval du = face.surface().domain_u(), dv = face.surface().domain_v();
    return {uniform(du.min, du.max), uniform(dv.min, dv.max)};
}

// Every surface face's normal points out: a step of `step` along it leaves `inside`, a step against it
// enters. Planar faces are checked at their loops' control-polygon centroid pushed inward slightly.
inline void expect_outward(const Solid& solid, const std::function<bool(const Vec3&)>& inside, double step,
                           int samples_per_face = 200) {
    for (std::size_t f = 0; f < solid.faces().size(); ++f) {
        const Face& face = solid.faces()[f];
        if (face.kind() != Face::Kind::surface) {
            // A point inside the face: the average of points spread along its outer loop (inside for
            // the convex loops these tests use).
            Vec3 centroid{};
            int count = 0;
            for (const Coedge& c : face.loops()[0]) {
                const Interval d = c.edge->curve.domain();
                for (double t : {0.125, 0.375, 0.625, 0.875}) {
                    centroid += c.edge->curve.point(d.min + t * (d.max - d.min));
                    ++count;
                }
            }
            centroid = centroid / count;
            const Vec3 n = face.plane().normal;
            EXPECT_TRUE(inside(centroid - n * step)) << "planar face " << f;
            EXPECT_FALSE(inside(centroid + n * step)) << "planar face " << f;
            continue;
        }
        for (int k = 0; k < samples_per_face; ++k) {
            auto [u, v] = random_parameter(face);
            const Vec3 p = face.point(u, v), n = face.normal(u, v);
            ASSERT_NEAR(norm(n), 1.0, 1e-12);
            EXPECT_TRUE(inside(p - n * step)) << "face " << f << " at (" << u << ", " << v << ")";
            EXPECT_FALSE(inside(p + n * step)) << "face " << f << " at (" << u << ", " << v << ")";
        }
    }
}

}  // namespace ratbez::test
