#pragma once
// Matching the sections of a ruled surface or a loft to one another before they are joined index by index
// (the alignment of issue 26): without it, point u of one section is ruled to point u of the next, so two
// circles whose parameterisations start at different angles, or a circle and a square (4 segments against
// 4 arcs placed elsewhere), give a twisted hourglass. Defined in section_alignment.cpp. Not installed, not
// part of the public API.
//
// Closed sections (each ending where it starts):
//  1. orientation: each section runs the way the one before it runs (the sign of the dot product of their
//     area vectors (1/2) sum P_i x P_{i+1} over 128 points equally spaced in arc length; where that is
//     not decisive, below a tenth of the product of the lengths, both ways are tried in step 2 and the
//     lower twist wins); `keep_orientation` skips this (loft() orients its planar profiles by the travel);
//  2. start point: the first section keeps its own; section k + 1 starts at the point that minimises the
//     twist measure E(s0) = integral_0^1 |C_{k+1}(s + s0) - C_k(s)|^2 ds, the mean squared length of the
//     rulings when both are parameterised by normalised arc length s (the total ruling length is the
//     measure the issue names; E is its smooth relative: both are minimised by the rotation that makes
//     every ruling as short as it can be where one exists, as between a section and the same section turned
//     about the loft's axis, and E's minimiser is the root of a smooth derivative, so it is found to
//     rounding: a circle lofted to itself turned 120 degrees comes out a cylinder to 1e-13). The search:
//     all 128 shifts by whole samples, then the root of E'(s0) (64-point midpoint rule, spectral for a
//     periodic integrand) between the best one's neighbours by regula falsi;
// Open sections: each is reversed when that brings its ends nearer to the previous section's ends
// (|a0 - b0| + |a1 - b1| against |a0 - b1| + |a1 - b0|), and starts at its start.
// Then every section is matched to every other by normalised arc length: the breakpoints of all sections
// (their knots, mapped to normalised arc length from the chosen start) are merged into one list (values
// closer than 1e-9 taken as one), every section is cut at the parameters where it reaches those lengths,
// each piece (a single Bézier span) put in normal form when rational (end weights 1: the one rational
// parameterisation of an arc that depends on the arc alone, so that equal arcs of two circles match point
// for point) and mapped linearly onto its interval of normalised length. A break where every section runs on
// within one Bézier piece of its degree (a straight segment, or an arc of one conic up to 120 degrees:
// bezier_merge.hpp) is dropped and the pieces on both sides merged: a circle's own arc joints opposite the
// middle of a square's sides leave no knot behind, so a circle lofted to a square has knots at the square's
// corners only, as Part's Loft has edges there. Last, a break where every section is C1 or smoother in its own
// parameter (no knot of multiplicity p there once every removable knot is removed, A5.8) is dropped too:
// mapped linearly piece by piece, the sections would be C0 in the common parameter at every such break (the
// geometry smooth), a line OpenCASCADE takes as a face edge, so closed interpolations with knots at unrelated
// lengths gave 16 side faces where Part's Loft of them gives one or two. Between two breaks that stay (a corner,
// a circle's arc joint, a line meeting an arc: C0 in some section's parameter), each section runs on its own
// parameter mapped linearly, its knots and continuity kept. So the sections share one knot vector
// (make_compatible: multiplicity p at every break that stays, the sections' own knots merged between), match
// exactly by arc length at every break and at the starts, and in between by their own parameters.

#include <string>
#include <vector>

#include "ratbez/nurbs_curve.hpp"

namespace ratbez::detail {

struct AlignedSections {
    std::vector<NurbsCurve> curves;  // on [0, 1], one degree, one knot vector (breaks with multiplicity p each)
    std::vector<double> breaks;      // the breakpoints that stay, 0 and 1 included
    bool closed = false;
};

// Throws Error naming `argument` when some sections are closed and others open, or a section has no length.
AlignedSections align_sections(const std::vector<NurbsCurve>& sections, const std::string& argument,
                               bool keep_orientation = false);

// Closed curves on [0, 1] (the aligned sections) each started at `parameter` (a knot of each): the part over
// [parameter, 1] followed by the part over [0, parameter], on [0, 1] again. The matching is unchanged.
std::vector<NurbsCurve> restarted_at(const std::vector<NurbsCurve>& sections, double parameter);

// The parameters, among the interior knots shared by compatible sections (one clamped knot vector on
// [0, 1]) and, for closed sections, 0, where every section has a corner (its tangent turns by more than
// 1e-7 rad): creases that run from the first section to the last, where a lofted solid gets an edge
// between two side faces.
std::vector<double> full_creases(const std::vector<NurbsCurve>& sections, bool closed);

}  // namespace ratbez::detail
