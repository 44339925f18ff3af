#pragma once
// Area and volume of exact solids by adaptive Gauss–Legendre cubature on the rational Bézier pieces of
// every face (volume by the divergence theorem: V = 1/3 of the integral of S . n dA over the closed
// boundary), to about 1e-14 of the solid's size squared (area) or cubed (volume), however extreme the
// rational weights. The work is bounded: where the weights crowd a face into too small a parameter
// range for that (beyond about 1e300 : 1 within one piece, or very many such pieces), Error says the
// accuracy cannot be reached instead of returning an unverified number.

#include "ratbez/brep.hpp"
#include "ratbez/progress.hpp"

namespace ratbez {

double surface_area(const Face& face);
double surface_area(const NurbsSurface& surface);  // the whole untrimmed surface
double surface_area(const Solid& solid);
double enclosed_volume(const Solid& solid);

// The same, polling `progress` (with 0) every few thousand cubature cells and calling it with 1 at the end:
// a Ctrl-C check for solids whose extreme weights need very many cells (an ordinary solid takes a
// millisecond). The callback may throw to cancel (progress.hpp).
double surface_area(const Solid& solid, const Progress& progress);
double enclosed_volume(const Solid& solid, const Progress& progress);

// Both, measured side by side on two threads: for a solid read from a file each cubature takes seconds (a 51-face
// screw: 2.4 s apiece). The same numbers as surface_area and enclosed_volume.
struct SolidMeasures {
    double area = 0, volume = 0;
};
SolidMeasures measure(const Solid& solid);

}  // namespace ratbez
