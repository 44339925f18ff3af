#pragma once
// Edges of ours that are, exactly, a segment or an arc of a circle or an ellipse, found as such for OpenCASCADE's own
// line, circle and ellipse. Internal to kernel/occt.
//
// Why: Part's edges are lines and circles, and OCCT treats its analytic curves better than the same curve as a
// rational B-spline: its sweeps make planes, cylinders, spheres and tori of them (swept_solids.hpp), and it
// projects a circle onto a sphere exactly (ProjLib) where the B-spline's projection is a fit: a sphere minus a box
// written to STEP with B-spline edges came back from FreeCAD's reader with p-curves 4.4e-6 off their edges,
// "BOPAlgo InvalidCurveOnSurface" (elementary_faces.hpp). Found on the kernel's control points (smooth_arcs.hpp for
// arcs), each to a tolerance in model units.

#include <gp_Circ.hxx>
#include <gp_Elips.hxx>

#include <optional>
#include <utility>

#include "ratbez/brep.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::occt::detail {

// The largest magnitude of a coordinate in the box: how far out the solid's digits are.
double reach(const Box& box);

// How far a control point may be from the line or arc an edge of `solid` is taken for: 1e-11 of its size, or of
// its distance from the origin if larger (a small solid far out has its control points only to the rounding of
// its coordinates: 1e4 out, ~1e-12, which a fit to its size alone would miss).
double exact_fit(const Solid& solid);

// The circle an edge runs on: the kernel's rational quadratic arc of a circle (not an ellipse), its frame as
// found (x from the centre towards the arc frame's start, normal so that the arc turns counterclockwise).
struct EdgeCircle {
    Vec3 centre, normal, x;
    double radius = 0;
    double sweep = 0;  // radians, at most 2 pi
};
std::optional<EdgeCircle> edge_circle(const Edge& e, double tolerance);

// The ellipse an edge runs on: the kernel's rational quadratic arc of an ellipse that is not a circle (a slanted
// hole's rim on a plane, read from a file), in its principal frame (x along the major axis, normal so that the arc
// turns counterclockwise). The kernel's arc is the ellipse's conjugate diameters U cos t + V sin t about the centre;
// OCCT's parameter is the same eccentric angle, measured from the major axis.
struct EdgeEllipse {
    Vec3 centre, normal, x;
    double major = 0, minor = 0;
    double sweep = 0;  // radians, at most 2 pi
};
std::optional<EdgeEllipse> edge_ellipse(const Edge& e, double tolerance);

// The parameters (first, last) on `circle` (OCCT's angle) of an arc of it turning counterclockwise from `start`
// through `middle` to `end` (all the way round when `closed`); nullopt when the middle is not on that turn.
std::optional<std::pair<double, double>> arc_range(const gp_Circ& circle, const gp_Pnt& start, const gp_Pnt& middle, const gp_Pnt& end,
                                    bool closed);

// The edge's ends as parameters on `circle` or `ellipse` (as arc_range, through the edge's middle point; on an
// ellipse OCCT's eccentric angle); nullopt unless that turn is `sweep` (the two arcs through the ends of a half circle are told apart by the middle).
std::optional<std::pair<double, double>> arc_parameters(const gp_Circ& circle, const Edge& e, double sweep);
std::optional<std::pair<double, double>> arc_parameters(const gp_Elips& ellipse, const Edge& e, double sweep);

// Whether every control point of a non-closed edge lies within `tolerance` of the segment between its ends (its
// image is then that segment: the convex hull; its parameter may run at any pace).
bool is_segment(const Edge& e, double tolerance);

// Whether the edge is a segment run at constant speed: a polynomial curve (equal weights) whose control points lie,
// within `tolerance`, where the straight line from its start to its end puts its Greville abscissae (a curve is
// linear in its parameter exactly then: the B-spline form of t is the Greville abscissae). Then OCCT's line over
// the edge's parameter scaled by its speed is the same curve with the same parameter up to that scale.
bool runs_linearly(const Edge& e, double tolerance);

}  // namespace ratbez::occt::detail
