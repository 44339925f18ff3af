#pragma once
// The classic solids as exact rational B-reps (see brep.hpp for the face structure):
//  cylinder: one lateral face (circle x segment, seam on the frame's x axis) and two planar caps;
//  cone:     one lateral face and one or two planar caps (radius2 == 0 ends in an apex, a degenerate edge;
//            radius1 == 0 puts the apex at the base; radii >= 0, not both 0);
//  sphere:   one face, a semicircle revolved 360 degrees, with degenerate edges at both poles;
//  torus:    one face, a circle revolved 360 degrees, two seams.
// `center` is the base center (cylinder, cone) or the center; `axis` need not be unit length.

#include "ratbez/brep.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

Solid cylinder(double radius, double height, const Vec3& center = {}, const Vec3& axis = {0, 0, 1});
Solid cone(double radius1, double radius2, double height, const Vec3& center = {}, const Vec3& axis = {0, 0, 1});
Solid sphere(double radius, const Vec3& center = {});
Solid torus(double major_radius, double minor_radius, const Vec3& center = {}, const Vec3& axis = {0, 0, 1});

}  // namespace ratbez
