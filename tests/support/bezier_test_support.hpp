#pragma once
// Test support for the Bézier suites (bernstein, power_basis, bezier_curve, bezier_surface).
//
// Exact rational arithmetic for test oracles: the worked examples and exercises of the source texts are
// recomputed here in fractions (independently of the kernel's floating-point code paths) and the kernel's
// doubles are compared against them. Overflow is checked, so an oracle can never silently wrap.

#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <random>
#include <string>
#include <stdexcept>
#include <vector>

#include "ratbez/vec.hpp"
#include "test_support.hpp"

namespace ratbez::test {

// 128-bit intermediates so a product of two 64-bit terms is exact before reduction (__extension__ keeps
// -Wpedantic quiet about the GCC/Clang builtin type).
__extension__ typedef __int128 Wide;

class Rational {
public:
    constexpr Rational(std::int64_t numerator = 0) : num_(numerator), den_(1) {}  // NOLINT: implicit on purpose
    Rational(std::int64_t numerator, std::int64_t denominator) : num_(numerator), den_(denominator) {
        if (den_ == 0) throw std::domain_error("Rational: zero denominator");
        normalize();
    }

    std::int64_t numerator() const { return num_; }
    std::int64_t denominator() const { return den_; }
    double to_double() const { return static_cast<double>(num_) / static_cast<double>(den_); }

    friend Rational operator+(const Rational& a, const Rational& b) {
        return from_wide(static_cast<Wide>(a.num_) * b.den_ + static_cast<Wide>(b.num_) * a.den_,
                         static_cast<Wide>(a.den_) * b.den_);
    }
    friend Rational operator-(const Rational& a, const Rational& b) { return a + Rational(-b.num_, b.den_); }
    friend Rational operator*(const Rational& a, const Rational& b) {
        return from_wide(static_cast<Wide>(a.num_) * b.num_, static_cast<Wide>(a.den_) * b.den_);
    }
    friend Rational operator/(const Rational& a, const Rational& b) {
        if (b.num_ == 0) throw std::domain_error("Rational: division by zero");
        return from_wide(static_cast<Wide>(a.num_) * b.den_, static_cast<Wide>(a.den_) * b.num_);
    }
    Rational& operator+=(const Rational& o) { return *this = *this + o; }
    Rational& operator-=(const Rational& o) { return *this = *this - o; }
    Rational& operator*=(const Rational& o) { return *this = *this * o; }
    friend bool operator==(const Rational& a, const Rational& b) { return a.num_ == b.num_ && a.den_ == b.den_; }

private:
    static Rational from_wide(Wide n, Wide d) {
        if (d < 0) { n = -n; d = -d; }
        Wide a = n < 0 ? -n : n, b = d;
        while (b != 0) { const Wide t = a % b; a = b; b = t; }
        if (a > 1) { n /= a; d /= a; }
        constexpr Wide limit = static_cast<Wide>(INT64_MAX);
        if (n > limit || -n > limit || d > limit) throw std::overflow_error("Rational: overflow in a test oracle");
        Rational r;
        r.num_ = static_cast<std::int64_t>(n);
        r.den_ = static_cast<std::int64_t>(d);
        return r;
    }
    void normalize() { *this = from_wide(num_, den_); }

    std::int64_t num_, den_;
};

// A point in exact homogeneous or Euclidean coordinates (w unused for Euclidean points).
struct RationalPoint {
    Rational x, y, z, w{1};

    friend RationalPoint operator+(const RationalPoint& a, const RationalPoint& b) {
        return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
    }
    friend RationalPoint operator*(const Rational& s, const RationalPoint& p) {
        return {s * p.x, s * p.y, s * p.z, s * p.w};
    }
    // H of Eq. 1.16, exactly.
    RationalPoint projected() const { return {x / w, y / w, z / w, Rational(1)}; }
    Vec3 to_vec3() const { return {x.to_double(), y.to_double(), z.to_double()}; }
    Vec4 to_vec4() const { return {x.to_double(), y.to_double(), z.to_double(), w.to_double()}; }
};

// The exact homogeneous point P^w = (w x, w y, w z, w) of Euclidean (x, y, z) with weight w.
inline RationalPoint homogeneous(Rational x, Rational y, Rational z, Rational w) {
    return {w * x, w * y, w * z, w};
}

// C(n, i) exactly.
inline Rational binomial(int n, int i) {
    if (i < 0 || i > n) return Rational(0);
    Rational c(1);
    for (int k = 1; k <= i; ++k) c = c * Rational(n - i + k, k);
    return c;
}

// Eq. 1.8 in exact arithmetic, straight from the closed form: B_{i,n}(u) = C(n,i) u^i (1-u)^{n-i}.
inline Rational bernstein_exact(int i, int n, const Rational& u) {
    if (i < 0 || i > n) return Rational(0);
    Rational value = binomial(n, i);
    for (int k = 0; k < i; ++k) value *= u;
    for (int k = 0; k < n - i; ++k) value *= (Rational(1) - u);
    return value;
}

// Eq. 1.7 / 1.17 exactly: sum_i B_{i,n}(u) P_i.
inline RationalPoint bezier_exact(const std::vector<RationalPoint>& points, const Rational& u) {
    RationalPoint sum{0, 0, 0, 0};
    const int n = static_cast<int>(points.size()) - 1;
    for (int i = 0; i <= n; ++i) sum = sum + bernstein_exact(i, n, u) * points[static_cast<std::size_t>(i)];
    return sum;
}

// Eq. 1.23 / 1.27 exactly, net[i][j] with i along u.
inline RationalPoint bezier_surface_exact(const std::vector<std::vector<RationalPoint>>& net, const Rational& u,
                                          const Rational& v) {
    RationalPoint sum{0, 0, 0, 0};
    const int n = static_cast<int>(net.size()) - 1;
    const int m = static_cast<int>(net.front().size()) - 1;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= m; ++j)
            sum = sum + (bernstein_exact(i, n, u) * bernstein_exact(j, m, v)) *
                            net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    return sum;
}

// Fixed-seed random input for the property tests: every run sees the same 1,000+ cases.
class RandomInput {
public:
    explicit RandomInput(std::uint64_t seed = 20240601) : engine_(seed) {}
    double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(engine_); }
    int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(engine_); }
    double parameter() { return uniform(0.0, 1.0); }
    Vec3 point(double extent = 10.0) { return {uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)}; }
    std::vector<Vec3> points(std::size_t count, double extent = 10.0) {
        std::vector<Vec3> result(count);
        for (auto& p : result) p = point(extent);
        return result;
    }
    std::vector<double> weights(std::size_t count, double low = 0.25, double high = 4.0) {
        std::vector<double> result(count);
        for (auto& w : result) w = uniform(low, high);
        return result;
    }

private:
    std::mt19937_64 engine_;
};

}  // namespace ratbez::test
