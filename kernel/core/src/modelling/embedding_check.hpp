#pragma once
// The refusal of surfaces that meet themselves (issue 26: never a silently invalid solid), shared by ruled
// surfaces, lofts and sweeps: the certified test of analysis/self_intersection.hpp run on the side surfaces,
// and an Error naming the argument, the cause and the place when it does not certify them. Defined in
// embedding_check.cpp. Not installed, not part of the public API.

#include <functional>
#include <string>

#include "analysis/self_intersection.hpp"

namespace ratbez::detail {

// Whether a side of the strip (u_min of the first piece, u_max of the last, when not closed in u; v_min or
// v_max, when not closed in v) is collapsed to a point: such surfaces (a ruling of zero length at an end) are
// one-to-one only up to that point, which the certificate does not cover; they are not checked.
bool has_collapsed_side(const SurfaceStrip& strip);

// Throws Error(argument, "the <what> meets itself near (x, y, z)<where(result)>; <advice>") unless the strip
// is certified not to meet itself (to 1e-7 of its size). A strip with a collapsed side passes unchecked.
void require_embedded(const SurfaceStrip& strip, const std::string& argument, const std::string& what,
                      const std::function<std::string(const SelfIntersection&)>& where, const std::string& advice);

}  // namespace ratbez::detail
