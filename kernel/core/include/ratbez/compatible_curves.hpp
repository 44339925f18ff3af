#pragma once
// Making NURBS curves compatible (The NURBS Book §8.4, §10.3): the same degree, the same domain and the same
// knot vector, so that their control polygons can be combined index by index into a surface (a ruled
// surface, a skinned loft). Every step changes the representation, never the curve:
//  - degree elevation (A5.9, DegreeElevateCurve): each Bézier span raised t degrees, interior knots keep
//    their continuity (multiplicity s becomes s + t), all on the homogeneous points P^w;
//  - the domain mapped affinely onto [0, 1] (NurbsCurve::reparameterized);
//  - knot refinement to the union of the knot vectors (A5.4, done as repeated Boehm insertion A5.1).

#include <string>
#include <vector>

#include "ratbez/degree_elevation.hpp"
#include "ratbez/nurbs_curve.hpp"

namespace ratbez {

// The curves on a common clamped knot vector over [0, 1], all of the highest degree among them; the k-th
// result is the k-th curve. Knots of different curves closer than 1e-12 (on [0, 1]) are taken as one,
// the later curve's knot moved onto the earlier's, which moves that curve by rounding only, instead of
// leaving a knot span of 1e-16 in every result. Throws Error naming `argument` when the list is empty.
std::vector<NurbsCurve> make_compatible(const std::vector<NurbsCurve>& curves, const std::string& argument = "curves");

}  // namespace ratbez
