// Ruled surfaces (The NURBS Book §8.4); see ruled.hpp.
#include "ratbez/ruled.hpp"

#include "modelling/embedding_check.hpp"
#include "modelling/section_alignment.hpp"
#include "ratbez/compatible_curves.hpp"

namespace ratbez {

NurbsSurface ruled_surface(const NurbsCurve& curve_a, const NurbsCurve& curve_b, bool align) {
    const std::vector<NurbsCurve> curves =
        make_compatible(align ? detail::align_sections({curve_a, curve_b}, "curve_b").curves : std::vector{curve_a, curve_b});
    const std::vector<Vec4>& a = curves[0].homogeneous_points();
    const std::vector<Vec4>& b = curves[1].homogeneous_points();
    std::vector<Vec4> net;
    net.reserve(2 * a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        net.push_back(a[i]);
        net.push_back(b[i]);
    }
    NurbsSurface surface = NurbsSurface::from_homogeneous(curves[0].degree(), 1, curves[0].knots(), {0.0, 0.0, 1.0, 1.0},
                                                          std::move(net), curves[0].is_rational() || curves[1].is_rational());
    // Closed curves close the strip in u (the aligned curves end where they start, their ends' rows equal).
    const bool closed = distance(curves[0].start_point(), curves[0].end_point()) <= 1e-9 * curves[0].control_box().diagonal() &&
                        distance(curves[1].start_point(), curves[1].end_point()) <= 1e-9 * curves[1].control_box().diagonal();
    detail::require_embedded({{surface}, closed, false}, "curve_b", "ruled surface", [](const detail::SelfIntersection&) { return std::string(); },
                             align ? "rulings that cross give no surface (these curves cannot be ruled without crossing)"
                                   : "rulings that cross give no surface; align=True matches the curves by arc length from the start of least twist");
    return surface;
}

}  // namespace ratbez
