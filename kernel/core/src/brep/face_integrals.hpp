#pragma once
// The walk over a shell's faces onto the integration engine (analysis/cubature.hpp): the enclosed volume
// by the divergence theorem and the area, for the measures of properties.hpp and a Solid's orientation
// check. Not installed, not part of the public API.

#include <string_view>
#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::detail {

// Signed volume enclosed by closed faces (divergence theorem), to about 1e-14 of their size cubed;
// `quick` takes a fixed low-order rule instead, enough for the sign (Solid's orientation check).
// Throws Error naming `argument` when the accuracy cannot be reached within the cell budget. `progress`
// is polled (with 0) every few thousand cells, so that it can cancel (progress.hpp).
double faces_volume(const std::vector<Face>& faces, std::string_view argument, bool quick = false,
                    const Progress& progress = {});
// The area of faces, to about 1e-14 of their size squared; errors and progress as above.
double faces_area(const std::vector<Face>& faces, std::string_view argument, const Progress& progress = {});

}  // namespace ratbez::detail
