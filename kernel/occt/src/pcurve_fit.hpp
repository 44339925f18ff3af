#pragma once
// The p-curve of an edge on a trimmed face, in the face's own NURBS parameters and with the edge's own
// parameter: what Face::trimmed needs (surface(pcurve(t)) = edge.curve(t)), computed for a face read from a
// file, whose p-curves live in OpenCASCADE's parameters of the analytic surface (the angle of a cylinder; our
// exact rational form runs through it at another pace) and follow OpenCASCADE's parameter of the edge (a
// circle's angle; our exact rational circle again at another pace).
//
// Exact where the parameters agree: a B-spline or Bézier face (whose parameters we keep) with an edge we hold
// in OpenCASCADE's parameter (a line, a B-spline) and a p-curve with an exact 2D form takes that form as it
// is, when it lands on the edge. Otherwise fitted: points of the edge at parameters t_k are projected onto
// the surface (Newton from where OpenCASCADE's p-curve says the point is, so a seam
// is approached from the right side; a local Newton, no global search) and interpolated by a cubic B-spline in t (The NURBS Book A9.1), refined
// where the curve between the samples strays from the projection, until the fit agrees with the projections
// to 1e-3 of the face's tolerance. Where the projections fold (two land on one place: an edge far off its face,
// beyond the surface's corner), the file's own p-curve is fitted instead where it is in our parameters (a
// B-spline face), if it keeps within the face's tolerance of the edge. What the fit then carries is recorded: the distance between the surface along it and
// the edge (which includes the file's own gap between its 3D curve and its surface).
// Exposes OCCT types: kernel/occt's translation units only.

#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>

#include <functional>

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"

namespace ratbez::occt::detail {

struct FittedPcurve {
    NurbsCurve curve;         // 2D (z = 0), over the edge's domain, inside the surface's domain
    double deviation = 0;     // the largest distance between surface(curve(t)) and the edge at the checks
    bool exact = false;       // the file's p-curve taken as it is
};

class PcurveFitter {
public:
    // `surface`: the face's NURBS (our parameters); `size`: the solid's size, for the absolute tolerances.
    PcurveFitter(const NurbsSurface& surface, double size);

    // The p-curve of `edge` on the surface. `guess(t)` says roughly where the edge's point at t is in (u, v)
    // (OpenCASCADE's p-curve, mapped to our parameters; `guess_exact` when the mapping is exact, as on a B-spline
    // face, not a rational form of an analytic one); `exact_candidate`, when not null, is a 2D curve the file
    // gives with the edge's own parameter. `tolerance` is the face's (the file's edge tolerance).
    FittedPcurve fit(const NurbsCurve& edge, const std::function<gp_Pnt2d(double)>& guess,
                     const NurbsCurve* exact_candidate, double tolerance, bool guess_exact = false);

private:
    // The (u, v) nearest to p, by Newton from `guess`; along a pole the free parameter keeps the guess's value.
    gp_Pnt2d project(const gp_Pnt& p, const gp_Pnt2d& guess);
    // The largest distance between surface(candidate(t)) and the edge's point at t, at 4 points per span.
    double deviation(const NurbsCurve& candidate, const NurbsCurve& edge) const;
    gp_Pnt2d clamped(const gp_Pnt2d& uv) const;

    const NurbsSurface& surface_;
    double size_;
    Handle(Geom_BSplineSurface) occt_;  // the same surface, for fast first derivatives
};

}  // namespace ratbez::occt::detail
