#pragma once
// NURBS curves C(u) = H{ sum N_{i,p}(u) P^w_i } with homogeneous control points (the B-spline
// generalisation of 000 §1.4; 001). Polynomial B-splines have all weights 1. At most limits::max_degree and
// limits::max_curve_points; rational weights are kept scaled by a power of two into (1/2, 1] (see
// BezierCurve), weights() gives them back as given.

#include <span>
#include <vector>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/box.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/control_points.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

class NurbsCurve : public ControlPolygon {
public:
    // Validates: degree >= 0 (degree >= 1 unless a single span), knots.size() == points.size() + degree + 1,
    // finite points, a valid knot vector, and (when given) as many weights as points, each finite and > 0.
    NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec3> points);
    NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec3> points, std::vector<double> weights);
    static NurbsCurve from_homogeneous(int degree, std::vector<double> knots, std::vector<Vec4> homogeneous_points,
                                       bool rational = true);
    // The Bézier curve as a NURBS on {0..0, 1..1} (001).
    static NurbsCurve from_bezier(const BezierCurve& curve);

    int degree() const { return degree_; }
    const std::vector<double>& knots() const { return knots_; }
    // is_rational(), homogeneous_points(), points() and weights(): ControlPolygon.
    Interval domain() const;
    // The box of the control points: it contains the curve (convex hull property).
    Box control_box() const;

    Vec3 point(double u) const;          // A4.1 (A3.1 on P^w, then H)
    Vec4 homogeneous_point(double u) const;
    // C^(k)(u), k = 0..order: A3.2 on P^w, then the rational quotient rule (A4.2).
    std::vector<Vec3> derivatives(double u, int order) const;
    // The same into out[0..k] for k = out.size() - 1, without allocating: the form for inner loops.
    void derivatives(double u, std::span<Vec3> out) const;
    Vec3 derivative(double u, int order = 1) const;

    // Knot insertion (A5.1, Boehm): u inserted r more times; the curve is unchanged.
    NurbsCurve insert_knot(double u, int times = 1) const;
    // The Bézier segments of every non-empty knot span, in order (A5.6 / repeated insertion).
    std::vector<BezierCurve> bezier_segments() const;
    // The same curve run backwards, on the mirrored knot vector.
    NurbsCurve reversed() const;
    // The same curve on the domain [a, b] (affine knot map), a < b.
    NurbsCurve reparameterized(double a, double b) const;
    // The same curve on the same domain with every Bézier span in normal form (BezierCurve::normal_form):
    // knots of multiplicity p at the span breaks, end weights 1 in every span. Each span keeps its own
    // parameter interval, so the curve is only C0 in its parameter at interior knots (its geometric
    // continuity is that of the curve). A polynomial curve is returned as it is.
    NurbsCurve normal_form() const;

    Vec3 start_point() const { return point(domain().min); }
    Vec3 end_point() const { return point(domain().max); }

private:
    friend class NurbsSurface;  // builds its isocurves, columns and rows without re-validating them
    // Unvalidated; the weights of pw are 2^weight_exponent times the ones weights() reports.
    NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec4> homogeneous_points, bool rational,
               int weight_exponent);
    int degree_ = 0;
    std::vector<double> knots_;
};

}  // namespace ratbez
