#pragma once
// Points and vectors in 3D, and homogeneous points (wx, wy, wz, w) with the projection H of Eq. 1.16.
// Rational curves and surfaces store their control points homogeneously (P^w), so every algorithm that
// works on polynomial points (A1.4, A1.5, A1.7, knot insertion, splitting) runs unchanged in 4D.

#include <cmath>

namespace ratbez {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
    friend constexpr Vec3 operator+(Vec3 a, const Vec3& b) { return a += b; }
    friend constexpr Vec3 operator-(Vec3 a, const Vec3& b) { return a -= b; }
    friend constexpr Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
    friend constexpr Vec3 operator*(Vec3 a, double s) { return a *= s; }
    friend constexpr Vec3 operator*(double s, Vec3 a) { return a *= s; }
    friend constexpr Vec3 operator/(const Vec3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
    friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
};

constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline double distance(const Vec3& a, const Vec3& b) { return norm(a - b); }
inline bool is_finite(const Vec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

// A homogeneous point P^w = (w x, w y, w z, w).
struct Vec4 {
    double x = 0, y = 0, z = 0, w = 0;

    constexpr Vec4& operator+=(const Vec4& o) { x += o.x; y += o.y; z += o.z; w += o.w; return *this; }
    constexpr Vec4& operator-=(const Vec4& o) { x -= o.x; y -= o.y; z -= o.z; w -= o.w; return *this; }
    constexpr Vec4& operator*=(double s) { x *= s; y *= s; z *= s; w *= s; return *this; }
    friend constexpr Vec4 operator+(Vec4 a, const Vec4& b) { return a += b; }
    friend constexpr Vec4 operator-(Vec4 a, const Vec4& b) { return a -= b; }
    friend constexpr Vec4 operator*(Vec4 a, double s) { return a *= s; }
    friend constexpr Vec4 operator*(double s, Vec4 a) { return a *= s; }
    friend constexpr bool operator==(const Vec4&, const Vec4&) = default;
};

// P^w from a Euclidean point and its weight.
constexpr Vec4 homogenize(const Vec3& p, double w) { return {w * p.x, w * p.y, w * p.z, w}; }
// The spatial part w*P of a homogeneous point (A(u) in the quotient-rule derivative formulas).
constexpr Vec3 weighted_part(const Vec4& p) { return {p.x, p.y, p.z}; }
// The projection H{P^w} = (x/w, y/w, z/w) of Eq. 1.16. Callers guarantee w > 0 (weights are validated
// positive, so every convex combination of them is too).
constexpr Vec3 project(const Vec4& p) { return {p.x / p.w, p.y / p.w, p.z / p.w}; }

// (1 - t) a + t b, the single step of every deCasteljau scheme (Eq. 1.12 / 1.19).
template <class V>
constexpr V lerp(const V& a, const V& b, double t) { return a * (1.0 - t) + b * t; }

}  // namespace ratbez
