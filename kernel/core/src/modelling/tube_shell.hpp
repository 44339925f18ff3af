#pragma once
// The B-rep of a tube: lateral surfaces side by side around closed loops (an outer profile and any holes),
// closed by two planar caps or, when the tube comes back to its start, by itself. Extrusions, lofts and
// sweeps all build this shape. Defined in tube_shell.cpp. Not installed, not part of the public API.

#include <optional>
#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/construction.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The outward normals of the two caps: at v_min (the start) and at v_max (the end).
struct CapNormals {
    Vec3 start, end;
};

// loops[0] is the outer loop, any further loops are holes. loops[l][k] runs u along piece k of a closed
// profile (piece k ends where piece k + 1 starts, the last where the first starts) and v along the tube,
// every surface over the same v domain, S_u x S_v outward (so holes run clockwise about the travel).
// Neighbouring surfaces share the isocurve of their common side (the trajectory of the joint), built once
// from loops[l][k]'s u_min side. With caps, the v_min and v_max boundaries bound two planar faces through
// the outer loop's first corner, one boundary loop per tube loop; without, the v_max boundary must be the
// v_min boundary (a closed tube: a torus) and the faces' v_min and v_max sides share their edges. The Solid
// constructor validates the result.
Solid tube_solid(const std::vector<std::vector<NurbsSurface>>& loops, const std::optional<CapNormals>& caps,
                 Construction construction = {});

// The same tube in bands along it, one face per surface: bands[b][k] is piece k of the loop over band b (a
// sweep's piece of path, where the surfaces are only C0), band b's v_max side band b + 1's v_min side; each band
// shares its ring of edges with the next, built from the later band's v_min side.
using TubeBands = std::vector<std::vector<NurbsSurface>>;
Solid tube_solid_in_bands(const std::vector<TubeBands>& loops, const std::optional<CapNormals>& caps, Construction construction = {});

}  // namespace ratbez::detail
