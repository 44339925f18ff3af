// The solids of issue 18 (lofts, ruled lofts, sweeps, exact and approximated) tessellate into meshes that
// CGAL accepts as solid boundaries: closed, 2-manifold, outward, free of self-intersections, with the exact
// volume within the tolerance times the area.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "modelling_test_support.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/export/mesh_checks.hpp"
#include "ratbez/loft.hpp"
#include "ratbez/properties.hpp"
#include "ratbez/sweep.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::exporter {
namespace {

void expect_cgal_clean(const Solid& solid, double tolerance, const std::string& name) {
    const Mesh mesh = tessellate(solid, tolerance);
    MeshCheckOptions options;
    options.exact_volume = enclosed_volume(solid);
    options.volume_tolerance = tolerance * mesh.area();
    const MeshReport report = check_mesh(mesh, options);
    EXPECT_TRUE(report.ok()) << name << ": " << (report.problems.empty() ? "" : report.problems.front());
}

TEST(ModellingMeshes, LoftsAndSweepsPassTheCgalChecks) {
    const std::vector<Profile> circles{Profile({circle(1.0)}), Profile({circle(2.0, {0, 0, 1})}), Profile({circle(1.0, {0, 0, 2})})};
    expect_cgal_clean(loft(circles), 2e-3, "loft");
    expect_cgal_clean(loft(circles, 3, true), 2e-3, "ruled loft");
    const Profile square({line_segment({1, 1, 0}, {-1, 1, 0}), line_segment({-1, 1, 0}, {-1, -1, 0}),
                          line_segment({-1, -1, 0}, {1, -1, 0}), line_segment({1, -1, 0}, {1, 1, 0})});
    expect_cgal_clean(loft({square, Profile({arc(1.2, 45, 405, {0, 0, 2})})}), 2e-3, "square to circle");
    expect_cgal_clean(sweep(Profile({circle(0.5, {2, 0, 0}, {0, 1, 0})}), circle(2.0)), 2e-3, "swept torus");
    const NurbsCurve path = test::helix_path(2.0, 0.4, 6);
    expect_cgal_clean(sweep(Profile({circle(0.3, path.start_point(), path.derivative(0.0))}), path), 2e-3, "helix sweep");
}

}  // namespace
}  // namespace ratbez::exporter
