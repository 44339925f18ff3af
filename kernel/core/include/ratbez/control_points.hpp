#pragma once
// Homogeneous control points P^w_i = (w_i P_i, w_i) (Eq. 1.16), stored once for every curve and surface
// class: a ControlPolygon for BezierCurve and NurbsCurve, a row-major ControlNet (net[i][j]: i along u,
// j along v) for BezierSurface and NurbsSurface, with the accessors they share. Rational weights are kept
// scaled by a power of two, 2^weight_exponent, into (1/2, 1] where they are extreme (so that no homogeneous
// point or sum overflows); the projection H is invariant under that common factor, and weights() gives
// the user's weights back exactly.

#include <cstddef>
#include <vector>

#include "ratbez/vec.hpp"

namespace ratbez {

class HomogeneousPoints {
public:
    const std::vector<Vec4>& homogeneous_points() const { return pw_; }
    // Whether the curve or surface is treated as rational (given weights); evaluation always projects.
    bool is_rational() const { return rational_; }

protected:
    HomogeneousPoints() = default;
    // Unvalidated; the weights of pw are 2^weight_exponent times the ones weights() reports.
    HomogeneousPoints(std::vector<Vec4> pw, bool rational, int weight_exponent);
    Vec3 point_at(std::size_t k) const { return project(pw_[k]); }  // P_k = H(P^w_k)
    double weight_at(std::size_t k) const;                          // w_k as given

    std::vector<Vec4> pw_;
    bool rational_ = false;
    int weight_exponent_ = 0;
};

class ControlPolygon : public HomogeneousPoints {
public:
    std::vector<Vec3> points() const;     // the Euclidean control points P_i
    std::vector<double> weights() const;  // the w_i as given (all 1 for a polynomial curve)

protected:
    using HomogeneousPoints::HomogeneousPoints;
};

class ControlNet : public HomogeneousPoints {
public:
    int rows() const { return rows_; }        // control points along u
    int columns() const { return columns_; }  // control points along v
    const Vec4& homogeneous_point(int i, int j) const { return pw_[static_cast<std::size_t>(i * columns_ + j)]; }
    std::vector<std::vector<Vec3>> points() const;     // net[i][j]
    std::vector<std::vector<double>> weights() const;  // as given, rows along u

protected:
    ControlNet() = default;
    // Unvalidated: rows x columns homogeneous points, row-major.
    ControlNet(int rows, int columns, std::vector<Vec4> pw, bool rational, int weight_exponent);

    int rows_ = 0, columns_ = 0;
};

}  // namespace ratbez
