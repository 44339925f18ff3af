#pragma once
// Tensor-product Bézier surfaces, polynomial and rational (000 §1.5, Eq. 1.27–1.28; 002).
// net[i][j]: i runs along u (degree n = rows - 1), j along v (degree m = columns - 1). Control points are
// stored homogeneously, row-major. The domain is [0,1] x [0,1]; parameters outside it throw ratbez::Error.
// Both degrees are at most limits::max_degree; rational weights are scaled as in BezierCurve.

#include <vector>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/control_points.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

class BezierSurface : public ControlNet {
public:
    explicit BezierSurface(std::vector<std::vector<Vec3>> net);
    BezierSurface(std::vector<std::vector<Vec3>> net, std::vector<std::vector<double>> weights);
    // rows x columns homogeneous points, row-major (index i * columns + j).
    static BezierSurface from_homogeneous(int rows, int columns, std::vector<Vec4> homogeneous_points,
                                          bool rational = true);

    int degree_u() const { return rows_ - 1; }
    int degree_v() const { return columns_ - 1; }
    // rows(), columns(), is_rational(), homogeneous_points(), homogeneous_point(i, j), points() and
    // weights(): ControlNet.

    // S(u, v); the default is the basis form on P^w (point_basis).
    Vec3 point(double u, double v) const;
    Vec3 point_basis(double u, double v) const;       // Bernstein values (A1.3) per direction, rows then column
                                                      // (the tensor-product scheme A1.6 applies to power bases)
    Vec3 point_u_first(double u, double v) const;     // A1.7: deCasteljau in u on each column j (giving the
                                                      // isocurve C_{u0}(v)'s points), then once in v
    Vec3 point_v_first(double u, double v) const;     // A1.7 in the other order: v on each row, then u
    Vec3 point_one_step(double u, double v) const;    // one-step (bilinear) deCasteljau of 002

    // d^{du+dv} S / du^du dv^dv at (u, v), rational ones by the quotient rule on S^w (Eq. 1.28 generalised).
    Vec3 derivative(double u, double v, int du, int dv) const;
    // SKL[k][l] for 0 <= k + l <= order.
    std::vector<std::vector<Vec3>> derivatives(double u, double v, int order) const;
    // Unit normal S_u x S_v / |.|; where one partial vanishes (a collapsed edge) the limit direction
    // from the mixed and second partials is used, so poles and apexes still get the right normal.
    // Throws Error naming "(u, v)" where no tangent plane exists (e.g. every control point the same).
    Vec3 normal(double u, double v) const;

    BezierCurve isocurve_u(double u0) const; // C_{u0}(v): the curve in v at fixed u = u0
    BezierCurve isocurve_v(double v0) const; // C_{v0}(u): the curve in u at fixed v = v0

private:
    friend class NurbsSurface;  // from_bezier keeps the weight scale
    // Unvalidated; the weights of pw are 2^weight_exponent times the ones weights() reports.
    BezierSurface(int rows, int columns, std::vector<Vec4> homogeneous_points, bool rational, int weight_exponent);
};

}  // namespace ratbez
