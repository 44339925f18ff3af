#pragma once
// Area and volume of exact solids by Gauss–Legendre quadrature on every knot span of every face
// (volume by the divergence theorem: V = 1/3 of the integral of S . n dA over the closed boundary).

#include "ratbez/brep.hpp"

namespace ratbez {

double surface_area(const Face& face);
double surface_area(const Solid& solid);
double enclosed_volume(const Solid& solid);

}  // namespace ratbez
