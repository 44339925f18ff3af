#pragma once
// Bézier curves, polynomial and rational in one class (000 §1.3–1.4). Control points are stored
// homogeneously as P^w_i = (w_i P_i, w_i) so that the rational curve C(u) = H{C^w(u)} (Eq. 1.16–1.19)
// is evaluated by the polynomial algorithms in 4D. A polynomial curve simply has every w_i = 1.
// The parameter domain is [0, 1]; parameters outside it throw ratbez::Error. The degree is at most
// limits::max_degree (26 control points). A rational curve keeps its weights scaled by a power of two into
// (1/2, 1] (weights() gives the user's back exactly), so that no homogeneous point or sum overflows.

#include <utility>
#include <vector>

#include "ratbez/control_points.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

class BezierCurve : public ControlPolygon {
public:
    // Polynomial curve through control points P_0..P_n (n >= 0); throws on empty or non-finite input.
    explicit BezierCurve(std::vector<Vec3> points);
    // Rational curve; weights.size() == points.size(), every weight finite and > 0.
    BezierCurve(std::vector<Vec3> points, std::vector<double> weights);
    // From homogeneous points P^w (w > 0); `rational` records whether the curve is to be treated as rational.
    // Evaluation always projects with H, so the curve is right whatever the flag says.
    static BezierCurve from_homogeneous(std::vector<Vec4> homogeneous_points, bool rational = true);

    int degree() const { return static_cast<int>(pw_.size()) - 1; }
    // is_rational(), homogeneous_points(), points() and weights(): ControlPolygon.

    // C(u) by A1.4 (Bernstein basis times homogeneous points, then H).
    Vec3 point(double u) const;
    // C(u) by deCasteljau in homogeneous space (A1.5 generalised by Eq. 1.19).
    Vec3 point_de_casteljau(double u) const;
    // C^w(u), the homogeneous point before projection.
    Vec4 homogeneous_point(double u) const;
    // The full deCasteljau triangle at u: rows[k][i] = P^w_{k,i}(u) (Table 1.4 of Ex1.14).
    std::vector<std::vector<Vec4>> de_casteljau_table(double u) const;

    // C^(k)(u) for k = 0..order, the rational derivatives by the quotient rule
    // C^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) C^(k-i)) / w, with A = weighted part of C^w.
    std::vector<Vec3> derivatives(double u, int order) const;
    Vec3 derivative(double u, int order = 1) const;

    // The two halves [0, u] and [u, 1], each reparameterised to [0, 1] (deCasteljau subdivision); 0 < u < 1.
    std::pair<BezierCurve, BezierCurve> split(double u) const;
    // The same curve with degree + 1 (degree elevation on P^w); Error naming "curve" at limits::max_degree.
    BezierCurve elevate() const;
    // The same curve traversed backwards: C_2(u) = C_1(1 - u) (Exercise 1.11).
    BezierCurve reversed() const;
    // The same curve in normal form: end weights w_0 = w_n = 1, reached by the Moebius reparameterisation
    // u = rho s / ((1 - s) + rho s), rho = (w_0 / w_n)^(1/n), which maps [0, 1] onto itself and multiplies
    // the weights by rho^i (see the .cpp). Uneven end weights crowd a curve's parameter towards one end;
    // the normal form spreads it evenly between the two. A polynomial curve is returned as it is, and so
    // is a rational one whose new weights would not be finite positive doubles.
    BezierCurve normal_form() const;

private:
    friend class NurbsCurve;  // from_bezier keeps the weight scale
    // Unvalidated; the weights of pw are 2^weight_exponent times the ones weights() reports.
    BezierCurve(std::vector<Vec4> homogeneous_points, bool rational, int weight_exponent);
};

}  // namespace ratbez
