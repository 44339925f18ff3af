#pragma once
// Right-handed orthonormal frames placed by an origin and an axis. Every primitive is built in its
// canonical frame (axis = z) and placed with one; the rule choosing the x direction is fixed, so the
// seam of a cylinder or sphere lands at the same place for the same axis every time.

#include "ratbez/vec.hpp"

namespace ratbez {

struct Frame {
    Vec3 origin, x_axis, y_axis, z_axis;

    Vec3 to_world(const Vec3& local) const {
        return origin + x_axis * local.x + y_axis * local.y + z_axis * local.z;
    }
    Vec3 direction_to_world(const Vec3& local) const {
        return x_axis * local.x + y_axis * local.y + z_axis * local.z;
    }
};

// The frame with z along `axis` (normalised; throws Error naming `argument` for a zero or non-finite axis).
// x is the global X axis projected into the plane normal to z, or the global Y axis when `axis` is
// within 1e-6 of X (the same rule OpenCASCADE's gp_Ax2(P, V) constructor follows is not promised).
Frame frame_from_axis(const Vec3& origin, const Vec3& axis, const char* argument = "axis");

}  // namespace ratbez
