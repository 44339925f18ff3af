// Bézier patches refined for OpenCASCADE's fixed Gauss rule (see gprop_patches.hpp).

#include "gprop_patches.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Precision.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "ratbez/occt/geometry.hpp"
#include "ratbez/properties.hpp"

namespace ratbez::occt::detail {
namespace {

// math::GaussPointsMax(): BRepGProp never uses more points per direction.
constexpr int kMaxGaussPoints = 61;
// Halvings of a cell whose rule misses the tolerance even at kMaxGaussPoints.
constexpr int kMaxHalvings = 3;
// The kernel's weight certificate (core/src/geometry/subdivision.hpp, kMaxWeightSpread): a patch whose weights vary
// by at most this factor along each line of control points has no pole of its rational integrand near
// the cell, so a Gauss rule of moderate size converges on it, and a rule that reads its area right reads its
// volume right too.
constexpr double kCertifiedWeightSpread = 4;
// Beyond the certificate a rule can match the area by chance, so such a cell must match OpenCASCADE's adaptive
// volume as well. A loft between a circle and a rounded square has cells of spread 5.2 (its interpolated weights
// dip between the sections, 0.98, 0.24, 1.25, 0.98), which the fixed rule reads to 1e-10 whole; halving them to
// the certificate made the example loft 28 faces instead of 11. Cells of extreme weights, beyond this spread,
// are halved first (bounded too): there no rule of 61 points converges.
constexpr double kMaxWeightSpread = 16;
constexpr int kMaxCertificateHalvings = 24;
// The degree a patch's v direction is raised to, one span, before it is cut (refine): order 24 of the rule.
constexpr int kMaxElevatedDegree = 11;
// Then subdivisions of a patch in v tried in turn (the rule grows with them until the cap).
constexpr int kVSpans[] = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32};

// The distinct knots within the domain: the lines between the surface's Bézier patches. The knots
// outside it (an unclamped knot vector, as OpenCASCADE reads back a periodic or extended surface: -0.25,
// 0, 0, ..., 1, 1.25) bound no patch.
std::vector<double> patch_lines(const std::vector<double>& knots, Interval domain) {
    std::vector<double> values;
    for (const double knot : knots)
        if (knot >= domain.min && knot <= domain.max && (values.empty() || knot != values.back())) values.push_back(knot);
    return values;
}

// The surface with every grid line a knot of full multiplicity, so that its Bézier patches are the cells.
NurbsSurface on_grid(NurbsSurface surface, const std::vector<double>& u, const std::vector<double>& v) {
    for (std::size_t i = 1; i + 1 < u.size(); ++i) {
        const auto count = std::count(surface.knots_u().begin(), surface.knots_u().end(), u[i]);
        if (count < surface.degree_u()) surface = surface.insert_knot_u(u[i], surface.degree_u() - static_cast<int>(count));
    }
    for (std::size_t j = 1; j + 1 < v.size(); ++j) {
        const auto count = std::count(surface.knots_v().begin(), surface.knots_v().end(), v[j]);
        if (count < surface.degree_v()) surface = surface.insert_knot_v(v[j], surface.degree_v() - static_cast<int>(count));
    }
    return surface;
}

// The largest max / min of the weights along one line of control points in u (along_u) or v.
double weight_spread(const BezierSurface& patch, bool along_u) {
    const int rows = patch.degree_u() + 1, columns = patch.degree_v() + 1;
    double spread = 1;
    for (int line = 0; line < (along_u ? columns : rows); ++line) {
        double low = std::numeric_limits<double>::infinity(), high = 0;
        for (int k = 0; k < (along_u ? rows : columns); ++k) {
            const double w = along_u ? patch.homogeneous_point(k, line).w : patch.homogeneous_point(line, k).w;
            low = std::min(low, w);
            high = std::max(high, w);
        }
        spread = std::max(spread, high / low);
    }
    return spread;
}

// Adds the middle of [lines[k], lines[k + 1]] for every k in `cells`, keeping `lines` sorted.
void halve(std::vector<double>& lines, const std::set<std::size_t>& cells) {
    std::vector<double> middles;
    for (std::size_t k : cells) middles.push_back(0.5 * (lines[k] + lines[k + 1]));
    lines.insert(lines.end(), middles.begin(), middles.end());
    std::sort(lines.begin(), lines.end());
}

// The area OCCT's fixed rule gives the face of the whole patch (BRepGProp::SurfaceProperties, no eps).
double fixed_rule_area(const Handle(Geom_BSplineSurface)& patch) {
    BRepBuilderAPI_MakeFace make(patch, Precision::Confusion());
    const TopoDS_Shape face = make.Shape();
    GProp_GProps properties;
    BRepGProp::SurfaceProperties(face, properties);
    return properties.Mass();
}

// The volume of the cone from `apex` over the face of the whole patch (BRepGProp::VolumeProperties of one face):
// by the fixed rule FreeCAD's Shape.Volume uses (eps = 0), or adaptively to the relative `eps`.
double patch_volume(const Handle(Geom_BSplineSurface)& patch, const gp_Pnt& apex, double eps = 0) {
    BRepBuilderAPI_MakeFace make(patch, Precision::Confusion());
    GProp_GProps properties(apex);
    if (eps > 0)
        BRepGProp::VolumeProperties(make.Shape(), properties, eps);
    else
        BRepGProp::VolumeProperties(make.Shape(), properties);
    return properties.Mass();
}

// Whether the fixed rule reads the patch's volume flux as OpenCASCADE's adaptive rule does, to
// `relative_tolerance` of the cone from its box's corner (the flux about the centre can cancel to nothing).
bool reads_volume(const Handle(Geom_BSplineSurface)& patch, double area, double relative_tolerance) {
    Bnd_Box box;
    for (int i = 1; i <= patch->NbUPoles(); ++i)
        for (int j = 1; j <= patch->NbVPoles(); ++j) box.Add(patch->Pole(i, j));
    const gp_Pnt corner = box.CornerMin();
    const double scale = area * box.CornerMin().Distance(box.CornerMax()) / 3;
    return std::abs(patch_volume(patch, corner) - patch_volume(patch, corner, 1e-12)) <= relative_tolerance * scale;
}

// The patch with its v direction raised to `degree` and cut into `spans` equal knot spans.
Handle(Geom_BSplineSurface) refined(const Handle(Geom_BSplineSurface)& patch, int degree, int spans) {
    Handle(Geom_BSplineSurface) copy = Handle(Geom_BSplineSurface)::DownCast(patch->Copy());
    if (degree > copy->VDegree()) copy->IncreaseDegree(copy->UDegree(), degree);
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    copy->Bounds(u0, u1, v0, v1);
    for (int k = 1; k < spans; ++k) copy->InsertVKnot(v0 + (v1 - v0) * k / spans, 1, Precision::PConfusion());
    return copy;
}

struct Refinement {
    Handle(Geom_BSplineSurface) patch;
    bool reached = false;
};

// The first refinement (in rule size) whose fixed-rule area is within the tolerance of `exact`, and its volume
// too when `check_volume`. Degree elevation first, one span: the patch stays one polynomial piece, infinitely
// smooth, as Part's own lofts are (degree 8); OpenCASCADE's fillets and chamfers fail on a face whose curvature
// jumps at a simple knot (a loft's patch cut in two at degree 2: C1). Knots only beyond kMaxElevatedDegree.
Refinement refine(const Handle(Geom_BSplineSurface)& patch, double exact, double relative_tolerance, bool check_volume) {
    const int q = patch->VDegree();
    const int u_order = gprop_integration_order(patch->UDegree(), 1);
    std::vector<std::pair<int, int>> candidates;  // (degree, spans)
    for (int degree = q; degree <= std::max(q, kMaxElevatedDegree); ++degree) candidates.emplace_back(degree, 1);
    for (int spans : kVSpans)
        if (spans > 1) candidates.emplace_back(std::max(q, 2), spans);  // simple knots at degree 1 would be C0
    Refinement best;
    int previous_order = 0;
    for (const auto& [degree, spans] : candidates) {
        const int order = std::min(kMaxGaussPoints, gprop_integration_order(degree, spans));
        if (order <= previous_order || order < u_order) continue;
        previous_order = order;
        best.patch = refined(patch, degree, spans);
        if (std::abs(fixed_rule_area(best.patch) - exact) <= relative_tolerance * exact &&
            (!check_volume || reads_volume(best.patch, exact, relative_tolerance))) {
            best.reached = true;
            return best;
        }
        if (order >= kMaxGaussPoints) break;
    }
    return best;
}

}  // namespace

int gprop_integration_order(int degree, int spans) { return std::max(8, 2 * std::max(4, (degree + 1) * spans)); }

PatchGrid gprop_patch_grid(const NurbsSurface& surface, double relative_tolerance) {
    PatchGrid grid;
    grid.u = patch_lines(surface.knots_u(), surface.domain_u());
    grid.v = patch_lines(surface.knots_v(), surface.domain_v());
    // First the columns / rows of cells whose weights spread too far along u / v for any rule are halved.
    for (int round = 0; round < kMaxCertificateHalvings; ++round) {
        const auto patches = on_grid(surface, grid.u, grid.v).bezier_patches();
        std::set<std::size_t> columns, rows;
        for (std::size_t i = 0; i + 1 < grid.u.size(); ++i)
            for (std::size_t j = 0; j + 1 < grid.v.size(); ++j) {
                if (weight_spread(patches[i][j], true) > kMaxWeightSpread) columns.insert(i);
                if (weight_spread(patches[i][j], false) > kMaxWeightSpread) rows.insert(j);
            }
        if (columns.empty() && rows.empty()) break;
        halve(grid.u, columns);
        halve(grid.v, rows);
    }
    // Then each cell refined for OCCT's rule; a cell that misses even at the cap halves its column and row.
    for (int round = 0;; ++round) {
        const auto patches = on_grid(surface, grid.u, grid.v).bezier_patches();
        grid.cells.clear();
        grid.reached = true;
        std::set<std::size_t> columns, rows;
        for (std::size_t i = 0; i + 1 < grid.u.size(); ++i)
            for (std::size_t j = 0; j + 1 < grid.v.size(); ++j) {
                const NurbsSurface cell = NurbsSurface::from_bezier(patches[i][j]);
                const bool certified = weight_spread(patches[i][j], true) <= kCertifiedWeightSpread &&
                                       weight_spread(patches[i][j], false) <= kCertifiedWeightSpread;
                const Refinement refinement = refine(to_occt(cell), surface_area(cell), relative_tolerance, !certified);
                grid.cells.push_back(refinement.patch);
                if (!refinement.reached) {
                    grid.reached = false;
                    columns.insert(i);
                    rows.insert(j);
                }
            }
        if (grid.reached || round == kMaxHalvings) return grid;
        halve(grid.u, columns);
        halve(grid.v, rows);
    }
}

}  // namespace ratbez::occt::detail
