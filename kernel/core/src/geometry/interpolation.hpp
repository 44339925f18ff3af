#pragma once
// Global B-spline interpolation (The NURBS Book §9.2.1–9.2.2, A9.1): the control points of the degree-p
// curve on a knot vector that passes through data at given parameters, with optional derivative
// conditions. Shared by the public fitting functions (ratbez/interpolation.hpp, ratbez/approximation.hpp:
// curves, surfaces by A9.4) and by skinning (loft.cpp, on homogeneous points). Defined in
// interpolation.cpp. Not installed, not part of the public API.

#include <string>
#include <vector>

#include "math/banded_system.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The clamped knot vector by averaging (Eq. 9.8): u_0..u_p = 0, u_{m-p}..u_m = 1 and
// u_{j+p} = (1/p) sum_{i=j}^{j+p-1} t_i for j = 1 .. n - p, for parameters 0 = t_0 <= ... <= t_n = 1.
// It makes the interpolation system non-singular (Schoenberg–Whitney) and banded. A parameter listed
// twice (a point with a derivative condition) gives Eq. 9.22's knots for end derivatives.
std::vector<double> averaged_knots(const std::vector<double>& parameters, int degree);

// One row of an interpolation system: the curve's derivative of `order` (0: the point) at `parameter`.
struct Condition {
    double parameter = 0;
    int order = 0;
};

// The system sum_j N^(order_k)_{j,p}(t_k) P_j = D_k (A9.1; with derivative rows, §9.2.2) on a clamped knot
// vector, one condition per control point, factored once (it is banded: at most p + 1 entries per row),
// so that every coordinate line of a surface (A9.4) reuses it. `ok()` is false when the system is
// singular (conditions that violate Schoenberg–Whitney).
class Collocation {
public:
    Collocation(int degree, const std::vector<double>& knots, const std::vector<Condition>& conditions);
    bool ok() const { return ok_; }
    // The control points for the data of each condition, in order (requires ok()).
    template <class T>
    std::vector<T> solve(std::vector<T> data) const {
        matrix_.solve(data);
        return data;
    }

private:
    BandedMatrix matrix_;
    bool ok_ = false;
};

// The control points P_j with sum_j N_{j,p}(t_k) P_j = D_k for every k (A9.1). Throws Error naming
// `argument` when the system is singular.
std::vector<Vec4> interpolate(int degree, const std::vector<double>& knots, const std::vector<double>& parameters,
                              const std::vector<Vec4>& data, const std::string& argument = "curves");

// Normalised cumulative chord lengths of a polyline (Eq. 9.5): t_0 = 0, t_k - t_{k-1} proportional to
// |Q_k - Q_{k-1}|^exponent (1: chord length, 1/2: centripetal Eq. 9.6, 0: uniform Eq. 9.3), t_n = 1; with
// `closed`, the chord from the last point back to the first is one more step (its parameter 1 is not
// listed). The caller has checked that consecutive points differ.
std::vector<double> chord_parameters(const std::vector<Vec3>& points, double exponent, bool closed);

// The parameters of a grid's rows (or columns) for surface interpolation (§9.2.5): every column's chord
// parameters (Eq. 9.5) averaged, leaving out the columns whose points all coincide (a pole: they say
// nothing about the spacing). lines[c][k] is point k of column c. Throws Error naming `argument` when no
// column moves or two consecutive averaged parameters coincide.
std::vector<double> averaged_parameters(const std::vector<std::vector<Vec3>>& lines, const std::string& argument,
                                        const std::string& what);

}  // namespace ratbez::detail
