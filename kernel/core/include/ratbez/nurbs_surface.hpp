#pragma once
// Tensor-product NURBS surfaces S(u,v) = H{ sum_i sum_j N_{i,p}(u) N_{j,q}(v) P^w_ij }.
// net[i][j]: i along u, j along v, as in BezierSurface; stored homogeneously, row-major. At most
// limits::max_degree in each direction and limits::max_surface_points; weights scaled as in BezierCurve.

#include <vector>

#include "ratbez/bezier_surface.hpp"
#include "ratbez/box.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/control_points.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

class NurbsSurface : public ControlNet {
public:
    NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                 std::vector<std::vector<Vec3>> net);
    NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                 std::vector<std::vector<Vec3>> net, std::vector<std::vector<double>> weights);
    // rows = knots_u.size() - degree_u - 1, columns = knots_v.size() - degree_v - 1; row-major P^w.
    static NurbsSurface from_homogeneous(int degree_u, int degree_v, std::vector<double> knots_u,
                                         std::vector<double> knots_v, std::vector<Vec4> homogeneous_points,
                                         bool rational = true);
    static NurbsSurface from_bezier(const BezierSurface& surface);

    int degree_u() const { return degree_u_; }
    int degree_v() const { return degree_v_; }
    const std::vector<double>& knots_u() const { return knots_u_; }
    const std::vector<double>& knots_v() const { return knots_v_; }
    // rows(), columns(), is_rational(), homogeneous_points(), homogeneous_point(i, j), points() and
    // weights(): ControlNet.
    Interval domain_u() const;
    Interval domain_v() const;
    // The box of the control points: it contains the surface (convex hull property).
    Box control_box() const;

    Vec3 point(double u, double v) const;      // A4.3
    using ControlNet::homogeneous_point;  // the control point (i, j), beside the evaluation
    Vec4 homogeneous_point(double u, double v) const;
    // SKL[k][l] = d^{k+l}S/du^k dv^l for 0 <= k + l <= order (A3.6 on P^w, then A4.4).
    std::vector<std::vector<Vec3>> derivatives(double u, double v, int order) const;
    Vec3 derivative(double u, double v, int du, int dv) const;
    // Unit normal; the limit direction where a partial vanishes (poles, apexes, points on the axis).
    Vec3 normal(double u, double v) const;

    NurbsCurve isocurve_u(double u0) const;  // the curve in v at fixed u = u0 (knots_v)
    NurbsCurve isocurve_v(double v0) const;  // the curve in u at fixed v = v0 (knots_u)

    NurbsSurface insert_knot_u(double u, int times = 1) const;  // A5.3
    NurbsSurface insert_knot_v(double v, int times = 1) const;
    // patches[a][b]: the Bézier patch of the a-th non-empty u span and b-th non-empty v span (A5.7).
    std::vector<std::vector<BezierSurface>> bezier_patches() const;

private:
    // Unvalidated; the weights of pw are 2^weight_exponent times the ones weights() reports.
    NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                 std::vector<Vec4> homogeneous_points, bool rational, int weight_exponent);
    NurbsCurve isocurve(bool fixed_u, double t0) const;  // isocurve_u (fixed_u) and isocurve_v
    int degree_u_ = 0, degree_v_ = 0;
    std::vector<double> knots_u_, knots_v_;
};

}  // namespace ratbez
