#pragma once
// Affine maps of faces and solids (the maps of affine_map.hpp): every surface, edge curve and vertex is
// mapped exactly, edges and vertices stay shared objects, and normals stay outward. A reflecting map
// (a mirror, a negative scaling) would turn every face inside out, so the image is reoriented: a surface
// face's parameters are swapped (S'(u, v) = S(v, u), whose S_u x S_v is the opposite of S's; its sides
// are permuted and their coedges reversed, every edge keeping its curve), and a planar face's loops are
// reversed.
//
// The construction record follows the map where the kind survives it: similarities (rigid motions,
// mirrors, uniform scalings) keep cylinders, cones, spheres, tori and revolutions, scaling their sizes;
// every affine map keeps an extrusion (a prism's image is a prism). Anything else becomes kind none.
//
// An image the limits of limits.hpp refuse (moved too far from the origin for its size, scaled past the
// coordinate limit) is an Error naming "map".

#include "ratbez/affine_map.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/construction.hpp"

namespace ratbez {

Face transformed(const Face& face, const AffineMap& map);
Solid transformed(const Solid& solid, const AffineMap& map);
Construction transformed(const Construction& construction, const AffineMap& map);

}  // namespace ratbez
