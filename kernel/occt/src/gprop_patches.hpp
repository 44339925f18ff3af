#pragma once
// The Bézier patches of a surface face, each refined so that OpenCASCADE's fixed Gauss rule measures it
// (ConvertOptions::bezier_faces). Internal to kernel/occt.
//
// Why: BRepGProp without an eps (what FreeCAD's Shape.Volume, Shape.Area and CenterOfMass call) integrates
// a face whose wire is not empty (ours never is) with ONE Gauss–Legendre rule over its whole parameter
// rectangle (BRepGProp_Gauss::Compute, the "domain" overloads): N points along the boundary's v and N
// along u, with N = min(61, max(IntegrationOrder of the pcurve, VIntegrationOrder)) for the volume and
// max(UIntegrationOrder, VIntegrationOrder) for the area, where (BRepGProp_Face)
//     U/VIntegrationOrder = max(8, 2 max(4, (degree + 1) (number of knot spans)))
// and a straight pcurve's IntegrationOrder is 4. Across a knot a rational B-spline face is only C0 or C1
// in its parameters (the rational quadratic circle: C1 with a jump in the second derivative), so one
// global rule converges slowly there: +0.93 % on the volume of a sphere of one face, and inserting knots
// only raises N up to the 61-point cap (3.7e-4). Within one Bézier patch the integrand is analytic, and
// the same rule converges geometrically: a sphere split into its 8 patches reads 1.7e-10.
//
// Each cell of the face's grid (its distinct knots, both directions) is therefore handed over as its own
// face. A cell's rule is then raised, if needed, by refining the patch in v only (v raises both N): first
// degree elevation, one span (the face stays infinitely smooth, as Part's lofts are: OCCT's offsets of a C1
// face are C0), then, beyond degree 11, uniform simple knots (a degree 1 direction elevated to 2 first, so
// that the face stays C1 and "Run BOP check" does not flag it GeomAbs_C0), until OCCT's own fixed rule on the
// patch matches the kernel's certified area to `relative_tolerance`, at least as many v points as u points
// (so that the volume, which only counts v, uses as many as the area); a cell whose weights spread beyond the
// kernel's certificate must also match OCCT's adaptive volume (there an area can match by chance). A cell
// that misses even at the 61-point cap (extreme rational weights) is halved in both directions, at most
// kMaxHalvings times, and cells of weights too extreme for any rule are halved before (gprop_patches.cpp).
// Knot insertion and degree elevation are exact; the geometry is the kernel's to rounding.

#include <Geom_BSplineSurface.hxx>

#include <vector>

#include "ratbez/nurbs_surface.hpp"

namespace ratbez::occt::detail {

struct PatchGrid {
    std::vector<double> u, v;  // grid lines, the domain's ends included
    // cells[i * (v.size() - 1) + j]: the patch on [u[i], u[i+1]] x [v[j], v[j+1]], refined as above, with
    // its parameters mapped affinely onto [0, 1] x [0, 1]. Not the face's own parameters: OCCT's check of a
    // face against itself (BOPAlgo_CheckerSI, part of FreeCAD's "Run BOP check") flags the patches at a
    // sphere's pole on some parameter ranges ([0.25, 0.5] x [0.5, 1] does, [0, 0.25] x [0.5, 1] does not:
    // its boundary test is in parameter units), and none on the unit square, for spheres of radius 0.1 to 1000.
    // (The handover then moves each column of cells along u to a range of its own: topology.cpp, u_shift_of.)
    std::vector<Handle(Geom_BSplineSurface)> cells;
    bool reached = true;  // every cell met the tolerance
    const Handle(Geom_BSplineSurface)& cell(std::size_t i, std::size_t j) const { return cells[i * (v.size() - 1) + j]; }
};

PatchGrid gprop_patch_grid(const NurbsSurface& surface, double relative_tolerance);

// The rule size BRepGProp_Face gives a B-spline direction of `degree` with `spans` knot spans.
int gprop_integration_order(int degree, int spans);

}  // namespace ratbez::occt::detail
