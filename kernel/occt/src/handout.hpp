#pragma once
// The solid as files, brep_string and check() hand it out, one place for both: convert's (topology.hpp), with
// faces still C0 inside split (c0_split.hpp), or OpenCASCADE's own primitive or sweep where ours is one
// (analytic_primitives.hpp, ConvertOptions::analytic_primitives), faces trimmed on a sphere, cylinder, cone or
// torus on OCCT's (elementary_faces.hpp) and arcs on OCCT's circles (circle_edges.hpp), both under the same
// option. Internal to kernel/occt; defined in topology.cpp beside to_occt.

#include "c0_split.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/progress.hpp"
#include "ratbez/occt/convert_options.hpp"
#include "ratbez/occt/topology.hpp"

namespace ratbez::occt::detail {

// Every face of the result traced to the face of `converted` it is (a piece of), so check() can name ours.
// `progress` is polled while faces are split (c0_split.hpp) and may throw to stop.
SplitSolid handed_out(const Solid& solid, const ConvertedSolid& converted, const ConvertOptions& options,
                      const Progress& progress = {});

}  // namespace ratbez::occt::detail
