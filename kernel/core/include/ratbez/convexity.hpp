#pragma once
// Whether a solid is convex, judged from its exact faces (convexity.cpp). A closed connected surface that is
// locally convex everywhere bounds a convex body (Tietze-Nakajima), so the judgement is local:
//  - one shell (a void makes any solid non-convex);
//  - every curved face bends away from its outward normal: its second fundamental form II = (L, M, N)
//    taken with the outward normal is negative semidefinite (L <= 0, N <= 0, LN - M^2 >= 0) at 5 points per
//    knot span and direction of its surface (the whole surface, not only a trimmed face's region: a face
//    whose surface turns inward outside its trim is judged non-convex, the safe side);
//  - every edge is a convex crease or smooth: at 3 points along it, each face's inward tangent leaving the
//    edge (into the face) does not rise above the other face's tangent plane.
// Sampled, so a dent narrower than the samples can go unseen; within 1e-9 of the solid's size per unit of
// curvature and of slope, flat is convex (a cylinder's rulings, a tangent edge).
// A solid whose construction record (construction.hpp) is a cylinder, a cone or a sphere is convex by that
// record, without sampling: the record is its builder's promise, as for its closed-form volume.
// tessellate() uses it to hand out convex meshes of convex solids (a mesh within the tolerance of a convex
// solid has a convex hull within the same tolerance), which OpenSCAD's hull() and minkowski() take fast;
// not where faces read from a file meet only within a tolerance that matters beside the mesh's (the hull
// bridges their gaps).

#include "ratbez/brep.hpp"

namespace ratbez {

bool is_convex(const Solid& solid);

}  // namespace ratbez
