#pragma once
// The sides of a surface face (brep.hpp's Side order: v_min, u_max, v_max, u_min), as both directions of the
// OCCT bridge walk them: topology.cpp building wires, shape_import.cpp reading them back.

#include "ratbez/brep.hpp"

namespace ratbez::occt::detail {

// Which way a face runs along side s (brep.hpp): v_min and u_max with increasing parameter, v_max and
// u_min decreasing.
inline bool traversal_increasing(int side) {
    return side == static_cast<int>(Side::v_min) || side == static_cast<int>(Side::u_max);
}
// Whether side s follows u (the v sides) or v (the u sides).
inline bool along_u(int side) { return side == static_cast<int>(Side::v_min) || side == static_cast<int>(Side::v_max); }

}  // namespace ratbez::occt::detail
