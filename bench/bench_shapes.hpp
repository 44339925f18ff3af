#pragma once
// The shapes every benchmark measures, built the same way in each program: the classic solids at unit
// size, a solid revolved from a rational cubic Bézier profile, and a random rational bicubic surface.
// No OCCT or CGAL header here, so every benchmark program can include it.

#include <cstddef>
#include <random>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"

namespace ratbez::bench {

// "a/b/c" from its parts. (Appending, rather than "literal" + std::string, which draws a false
// -Wrestrict from GCC 12, bug 105329.)
inline std::string benchmark_name(std::initializer_list<std::string_view> parts) {
    std::string name;
    for (std::string_view part : parts) {
        if (!name.empty()) name += '/';
        name += part;
    }
    return name;
}

// A rational cubic from the axis (z) out and back to it: a closed solid when revolved 360 degrees.
inline Solid revolved_rational_cubic() {
    const BezierCurve profile({{0, 0, 0}, {1.6, 0, 0.2}, {1.1, 0, 1.7}, {0, 0, 2}}, {1.0, 0.6, 1.8, 1.0});
    return revolve(Profile::from_beziers({profile}));
}

// A random rational bicubic NURBS on a 20 x 20 net (clamped uniform knots, 17 spans each way, weights
// 0.5..2): the general case with no structure to exploit. Seeded: the same surface in every run.
inline NurbsSurface random_bicubic(int net_size = 20) {
    std::mt19937_64 engine(20240611);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0), weight(0.5, 2.0);
    const int degree = 3;
    std::vector<double> knots;
    for (int k = 0; k <= degree; ++k) knots.push_back(0.0);
    for (int k = 1; k < net_size - degree; ++k) knots.push_back(static_cast<double>(k) / (net_size - degree));
    for (int k = 0; k <= degree; ++k) knots.push_back(1.0);
    std::vector<std::vector<Vec3>> net(static_cast<std::size_t>(net_size));
    std::vector<std::vector<double>> weights(static_cast<std::size_t>(net_size));
    for (int i = 0; i < net_size; ++i)
        for (int j = 0; j < net_size; ++j) {
            // A wavy sheet over the unit square, so the surface is not self-intersecting noise.
            net[static_cast<std::size_t>(i)].push_back({static_cast<double>(i) / net_size + 0.02 * coordinate(engine),
                                                        static_cast<double>(j) / net_size + 0.02 * coordinate(engine),
                                                        0.2 * coordinate(engine)});
            weights[static_cast<std::size_t>(i)].push_back(weight(engine));
        }
    return NurbsSurface(degree, degree, knots, knots, net, weights);
}

struct NamedSurface {
    std::string name;
    NurbsSurface surface;
};

// The four evaluation surfaces: sphere, torus and revolved cubic from their solids' (single) face.
inline std::vector<NamedSurface> evaluation_surfaces() {
    return {{"sphere", sphere(1.0).faces()[0].surface()},
            {"torus", torus(1.0, 0.3).faces()[0].surface()},
            {"revolved_cubic", revolved_rational_cubic().faces()[0].surface()},
            {"random_bicubic", random_bicubic()}};
}

struct NamedSolid {
    std::string name;
    Solid solid;
};

inline std::vector<NamedSolid> tessellation_solids() {
    return {{"sphere", sphere(1.0)},
            {"torus", torus(1.0, 0.3)},
            {"revolved_cubic", revolved_rational_cubic()},
            {"cylinder", cylinder(1.0, 2.0)}};
}

}  // namespace ratbez::bench
