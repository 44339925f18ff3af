// Ruled surfaces (The NURBS Book §8.4); see ruled.hpp.
#include "ratbez/ruled.hpp"

#include "ratbez/compatible_curves.hpp"

namespace ratbez {

NurbsSurface ruled_surface(const NurbsCurve& curve_a, const NurbsCurve& curve_b) {
    const std::vector<NurbsCurve> curves = make_compatible({curve_a, curve_b});
    const std::vector<Vec4>& a = curves[0].homogeneous_points();
    const std::vector<Vec4>& b = curves[1].homogeneous_points();
    std::vector<Vec4> net;
    net.reserve(2 * a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        net.push_back(a[i]);
        net.push_back(b[i]);
    }
    return NurbsSurface::from_homogeneous(curves[0].degree(), 1, curves[0].knots(), {0.0, 0.0, 1.0, 1.0},
                                          std::move(net), curves[0].is_rational() || curves[1].is_rational());
}

}  // namespace ratbez
