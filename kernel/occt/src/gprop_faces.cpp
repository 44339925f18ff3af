// Whole faces for OpenCASCADE's fixed Gauss rule (gprop_faces.hpp says why).

#include "gprop_faces.hpp"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <math.hxx>

#include <algorithm>
#include <utility>

#include "gprop_patches.hpp"

namespace ratbez::occt::detail {
namespace {

// The distinct interior knots of a direction with their multiplicities.
std::vector<std::pair<double, int>> knot_multiplicities(const NurbsSurface& surface, bool along_u) {
    const std::vector<double>& knots = along_u ? surface.knots_u() : surface.knots_v();
    const Interval domain = along_u ? surface.domain_u() : surface.domain_v();
    std::vector<std::pair<double, int>> inside;
    for (std::size_t k = 0; k < knots.size();) {
        std::size_t end = k;
        while (end < knots.size() && knots[end] == knots[k]) ++end;
        if (knots[k] > domain.min && knots[k] < domain.max)
            inside.emplace_back(knots[k], static_cast<int>(end - k));
        k = end;
    }
    return inside;
}

}  // namespace

std::vector<double> rough_knots(const NurbsSurface& surface, bool along_u) {
    const int degree = along_u ? surface.degree_u() : surface.degree_v();
    std::vector<double> rough;
    for (const auto& [knot, multiplicity] : knot_multiplicities(surface, along_u))
        if (multiplicity >= std::max(1, degree - 1)) rough.push_back(knot);
    return rough;
}

bool cut_on_sides(const Face& face, bool along_u) {
    const NurbsSurface& surface = face.surface();
    for (const auto& entry : knot_multiplicities(surface, along_u))
        if (entry.second >= (along_u ? surface.degree_u() : surface.degree_v())) return false;
    return !face.sides()[static_cast<std::size_t>(along_u ? Side::v_max : Side::u_max)].edge->degenerate;
}

Handle(Geom_BSplineSurface) refined_for_gauss(Handle(Geom_BSplineSurface) surface) {
    // A straight direction, and a one-span direction below cubic (a 3-section loft's quadratic v), that the
    // simple knots below go into.
    const auto raised = [](int degree, bool cut) { return degree == 1 || (cut && degree < 3) ? 3 : degree; };
    const int u_degree = raised(surface->UDegree(), surface->NbUKnots() == 2);
    const int v_degree = raised(surface->VDegree(), surface->NbVKnots() == 2);
    // Four spans, except for a quadratic raised to cubic: three keep the Gauss order it had at quadratic with four
    // (24 points, gprop_integration_order), so the reading is the same and OCCT's later work no dearer.
    const auto spans = [](int degree, int was) { return was == 2 && degree == 3 ? 3 : 4; };
    const int u_spans = spans(u_degree, surface->UDegree()), v_spans = spans(v_degree, surface->VDegree());
    if (u_degree != surface->UDegree() || v_degree != surface->VDegree()) surface->IncreaseDegree(u_degree, v_degree);
    if (surface->NbUKnots() == 2) {
        const double a = surface->UKnot(1), b = surface->UKnot(2);
        for (int k = 1; k < u_spans; ++k) surface->InsertUKnot(a + (b - a) * k / u_spans, 1, 0.0);
    }
    if (surface->NbVKnots() == 2) {
        const double a = surface->VKnot(1), b = surface->VKnot(2);
        for (int k = 1; k < v_spans; ++k) surface->InsertVKnot(a + (b - a) * k / v_spans, 1, 0.0);
    }
    return surface;
}

void with_v_rule_as_u(Geom_BSplineSurface& surface) {
    const int spans = surface.NbVKnots() - 1;
    const int u_order =
        std::min(math::GaussPointsMax(), gprop_integration_order(surface.UDegree(), surface.NbUKnots() - 1));
    const auto parts_needed = [&](int degree) {
        int parts = 1;
        while (gprop_integration_order(degree, spans * parts) < u_order) ++parts;
        return parts;
    };
    if (parts_needed(surface.VDegree()) == 1) return;
    // Cubic before the simple knots go in, as refined_for_gauss: at quadratic they made a 3-section loft's face
    // formally C1, and Part Offset of it (C0) was flagged by the BOP check, Thickness after a fillet raised.
    if (surface.VDegree() < 3) surface.IncreaseDegree(surface.UDegree(), 3);
    const int parts = parts_needed(surface.VDegree());
    if (parts == 1) return;
    TColStd_Array1OfReal knots(1, spans * (parts - 1));
    for (int k = 0; k < spans; ++k)
        for (int j = 1; j < parts; ++j) {
            const double a = surface.VKnot(k + 1), b = surface.VKnot(k + 2);
            knots.SetValue(k * (parts - 1) + j, a + (b - a) * j / parts);
        }
    TColStd_Array1OfInteger once(1, knots.Length());
    once.Init(1);
    surface.InsertVKnots(knots, once);
}

}  // namespace ratbez::occt::detail
