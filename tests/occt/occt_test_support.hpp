#pragma once
// Shared helpers of the OCCT cross-check suites: seeded random NURBS / Bézier geometry, a running
// maximum that each test prints, so the largest deviation measured is visible in the test log, and
// FreeCAD's BOP check.

#include <BOPAlgo_ArgumentAnalyzer.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::occt::testing {

// Whether FreeCAD's "Run BOP check" (Part > Check geometry) finds a fault: BOPAlgo_ArgumentAnalyzer in the modes
// FreeCAD switches on.
inline bool bop_check_finds_faults(const TopoDS_Shape& shape) {
    BOPAlgo_ArgumentAnalyzer analyzer;
    analyzer.SetShape1(shape);
    analyzer.SelfInterMode() = analyzer.SmallEdgeMode() = analyzer.ContinuityMode() = true;
    analyzer.CurveOnSurfaceMode() = analyzer.RebuildFaceMode() = true;
    analyzer.Perform();
    return analyzer.HasFaulty();
}

class Random {
public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(engine_); }
    int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(engine_); }
    bool coin(double p_true = 0.5) { return uniform(0, 1) < p_true; }
    Vec3 point(double half_size) {
        return {uniform(-half_size, half_size), uniform(-half_size, half_size), uniform(-half_size, half_size)};
    }

    // A valid flat knot vector for `degree` and `count` control points: clamped (end multiplicity
    // degree + 1) or not, interior knots with random multiplicities 1..degree, over a random interval.
    std::vector<double> knots(int degree, int count, bool clamped) {
        const int size = count + degree + 1;
        const double start = uniform(-3, 3);
        const double width = uniform(0.2, 5);
        for (;;) {
            std::vector<double> flat;
            int remaining = clamped ? size - 2 * (degree + 1) : size;
            std::vector<double> values;
            const int distinct_guess = std::max(1, remaining);
            // Distinct values first, sorted, then multiplicities until the vector is full.
            for (int i = 0; i < distinct_guess; ++i) values.push_back(uniform(start, start + width));
            std::sort(values.begin(), values.end());
            values.erase(std::unique(values.begin(), values.end()), values.end());
            if (clamped) flat.assign(static_cast<std::size_t>(degree + 1), start);
            for (double v : values) {
                if (remaining <= 0) break;
                const int multiplicity = std::min(remaining, integer(1, std::max(1, degree)));
                for (int k = 0; k < multiplicity; ++k) flat.push_back(v);
                remaining -= multiplicity;
            }
            if (remaining > 0) continue;  // too few distinct values drawn: draw again
            if (clamped) flat.insert(flat.end(), static_cast<std::size_t>(degree + 1), start + width);
            // OCCT demands distinct knots more than Epsilon apart and a non-empty domain.
            bool separated = true;
            for (std::size_t i = 1; i < flat.size(); ++i)
                if (flat[i] != flat[i - 1] && flat[i] - flat[i - 1] < 1e-3) separated = false;
            const std::size_t m = flat.size() - 1;
            if (!separated || !(flat[static_cast<std::size_t>(degree)] < flat[m - static_cast<std::size_t>(degree)])) continue;
            return flat;
        }
    }

    std::vector<double> weights(int count, bool rational) {
        std::vector<double> w(static_cast<std::size_t>(count), 1.0);
        if (rational)
            for (double& x : w) x = uniform(0.1, 10);
        return w;
    }

    NurbsCurve nurbs_curve() {
        const int degree = integer(1, 7);
        const int count = integer(degree + 1, degree + 9);
        std::vector<Vec3> points;
        const double half = uniform(0.1, 10);
        for (int i = 0; i < count; ++i) points.push_back(point(half));
        std::vector<double> knots_ = knots(degree, count, coin());
        if (coin(0.8)) return NurbsCurve(degree, std::move(knots_), std::move(points), weights(count, true));
        return NurbsCurve(degree, std::move(knots_), std::move(points));
    }

    NurbsSurface nurbs_surface() {
        const int degree_u = integer(1, 7), degree_v = integer(1, 7);
        const int rows = integer(degree_u + 1, degree_u + 6), columns = integer(degree_v + 1, degree_v + 6);
        const double half = uniform(0.1, 10);
        std::vector<std::vector<Vec3>> net(static_cast<std::size_t>(rows));
        std::vector<std::vector<double>> w(static_cast<std::size_t>(rows));
        for (int i = 0; i < rows; ++i) {
            for (int j = 0; j < columns; ++j) net[static_cast<std::size_t>(i)].push_back(point(half));
            w[static_cast<std::size_t>(i)] = weights(columns, true);
        }
        std::vector<double> ku = knots(degree_u, rows, coin()), kv = knots(degree_v, columns, coin());
        if (coin(0.8)) return NurbsSurface(degree_u, degree_v, std::move(ku), std::move(kv), std::move(net), std::move(w));
        return NurbsSurface(degree_u, degree_v, std::move(ku), std::move(kv), std::move(net));
    }

    BezierCurve bezier_curve() {
        const int degree = integer(1, 7);
        std::vector<Vec3> points;
        const double half = uniform(0.1, 10);
        for (int i = 0; i <= degree; ++i) points.push_back(point(half));
        if (coin(0.8)) return BezierCurve(std::move(points), weights(degree + 1, true));
        return BezierCurve(std::move(points));
    }

    BezierSurface bezier_surface() {
        const int degree_u = integer(1, 7), degree_v = integer(1, 7);
        const double half = uniform(0.1, 10);
        std::vector<std::vector<Vec3>> net(static_cast<std::size_t>(degree_u + 1));
        std::vector<std::vector<double>> w(static_cast<std::size_t>(degree_u + 1));
        for (int i = 0; i <= degree_u; ++i) {
            for (int j = 0; j <= degree_v; ++j) net[static_cast<std::size_t>(i)].push_back(point(half));
            w[static_cast<std::size_t>(i)] = weights(degree_v + 1, true);
        }
        if (coin(0.8)) return BezierSurface(std::move(net), std::move(w));
        return BezierSurface(std::move(net));
    }

private:
    std::mt19937_64 engine_;
};

// The bounding-box diagonal of a set of points: the "size" deviations are relative to.
inline double diagonal(const std::vector<Vec3>& points) {
    Vec3 lo = points.front(), hi = points.front();
    for (const Vec3& p : points) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    return norm(hi - lo);
}

inline std::vector<Vec3> flatten(const std::vector<std::vector<Vec3>>& net) {
    std::vector<Vec3> out;
    for (const auto& row : net) out.insert(out.end(), row.begin(), row.end());
    return out;
}

// Records the largest value seen and prints it when destroyed (visible with --gtest output / ctest -V).
class MaxTracker {
public:
    explicit MaxTracker(std::string label) : label_(std::move(label)) {}
    ~MaxTracker() { std::cout << "[ measured ] " << label_ << ": " << max_ << '\n'; }
    void add(double value) { max_ = std::max(max_, value); }
    double value() const { return max_; }

private:
    std::string label_;
    double max_ = 0;
};

}  // namespace ratbez::occt::testing
