#pragma once
// Evaluation of curves and surfaces at many parameters at once, into caller-owned interleaved (x, y, z)
// arrays: the layout numpy arrays of shape (..., 3) have, so the Python module hands its output buffers
// straight in.
//
// Parameters come in any order (repeats allowed) and are checked first: every one finite and inside the
// domain, else Error naming `argument` ("us", "vs", "uv") and the element. Surface grids go through the
// tensor-grid evaluator (surface_grid.hpp) for the point, the first and the second partials and the unit
// normals, a block of grid rows at a time (so its structure-of-arrays output stays in cache while it is
// interleaved); higher partials, curves and scattered (u, v) pairs are evaluated point by point. Every
// value agrees with the point-wise call (point, derivative, normal) to rounding.

#include <cstddef>
#include <span>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"

namespace ratbez {

// out[3 k .. 3 k + 2] = C^(order)(us[k]) (order 0: the point). out.size() == 3 us.size().
void evaluate_curve(const NurbsCurve& curve, std::span<const double> us, int order, std::span<double> out);
void evaluate_curve(const BezierCurve& curve, std::span<const double> us, int order, std::span<double> out);

// out[3 (i vs.size() + j) ..] = d^(du+dv) S / du^du dv^dv at (us[i], vs[j]). out.size() == 3 us.size() vs.size().
void evaluate_surface_grid(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                           int du, int dv, std::span<double> out);
// Every partial up to `order` (1 or 2) at each grid point, from one pass of the grid evaluator (the bases are
// computed once for all of them, as OpenCASCADE's D1 / D2 give them): m = 3 vectors per point for order 1
// (S, S_u, S_v), m = 6 for order 2 (then S_uu, S_uv, S_vv), out[3 ((i vs.size() + j) m + k) ..] = vector k.
// out.size() == 3 m us.size() vs.size().
void evaluate_surface_partials(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                               int order, std::span<double> out);
// The unit normals (NurbsSurface::normal: the limit direction at poles and apexes) on the same grid.
void evaluate_surface_normals(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                              std::span<double> out);
// out[3 k ..] = the (du, dv) partial at (uv[2 k], uv[2 k + 1]). out.size() == 3 (uv.size() / 2).
void evaluate_surface_at(const NurbsSurface& surface, std::span<const double> uv, int du, int dv,
                         std::span<double> out);

}  // namespace ratbez
