// The check that a construction record describes its faces (construction_check.hpp).
#include "ratbez/construction_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "math/numeric_internal.hpp"
#include "math/solid_scale.hpp"
#include "ratbez/error.hpp"

namespace ratbez {
namespace {

constexpr int kSamples = 9;

// The samples of a face: a kSamples x kSamples grid of a surface face's parameters (rows along v), or the
// points of a planar face's loop edges.
std::vector<std::vector<Vec3>> face_samples(const Face& face) {
    std::vector<std::vector<Vec3>> rows;
    if (face.kind() == Face::Kind::planar) {
        std::vector<Vec3> points;
        for (const auto& loop : face.loops())
            for (const Coedge& coedge : loop) {
                const Interval d = coedge.edge->curve.domain();
                for (int k = 0; k < kSamples; ++k) points.push_back(coedge.edge->curve.point(d.min + d.width() * k / (kSamples - 1)));
            }
        rows.push_back(std::move(points));
        return rows;
    }
    const NurbsSurface& s = face.surface();
    const Interval du = s.domain_u(), dv = s.domain_v();
    for (int i = 0; i < kSamples; ++i) {
        std::vector<Vec3> row;
        for (int j = 0; j < kSamples; ++j)
            row.push_back(s.point(du.min + du.width() * i / (kSamples - 1), dv.min + dv.width() * j / (kSamples - 1)));
        rows.push_back(std::move(row));
    }
    return rows;
}

// Height along the axis and distance from it.
struct Cylindrical {
    double height, radius;
};
Cylindrical cylindrical(const Vec3& p, const Vec3& origin, const Vec3& axis) {
    const Vec3 q = p - origin;
    const double height = dot(q, axis);
    return {height, norm(q - axis * height)};
}

class Checker {
public:
    Checker(std::span<const Face> faces, std::string_view argument) : argument_(argument) {
        Box box;
        for (const Face& face : faces) box.add(face.surface().control_box());
        size_ = box.diagonal();
        // As the B-rep's own consistency checks: 1e-9 of the size, and the rounding of coordinates that far out.
        tolerance_ = 1e-9 * size_ + 64 * std::numeric_limits<double>::epsilon() * detail::reach_of(box);
    }
    double tolerance() const { return tolerance_; }
    double size() const { return size_; }

    // Error unless `distance` (of a sample of face `index` from what the record names) is within tolerance.
    void require_within(double distance, std::size_t index, std::string_view kind, std::string_view what) const {
        require(distance <= tolerance_, argument_, [&] {
            return "the " + std::string(kind) + " record does not describe face " + std::to_string(index) + ": " +
                   std::string(what) + " " + detail::number(distance) + " away from it (the record must describe the faces; "
                   "a record from outside is checked)";
        });
    }

private:
    std::string_view argument_;
    double tolerance_ = 0, size_ = 0;
};

// The largest difference of (height, radius) along the rows (along == true: within each row; else within
// each column): 0 for circles about the axis.
double circle_spread(const std::vector<std::vector<Vec3>>& grid, const Vec3& origin, const Vec3& axis, bool along) {
    double worst = 0;
    const std::size_t n = grid.size(), m = grid.front().size();
    for (std::size_t a = 0; a < (along ? n : m); ++a) {
        const Vec3& first = along ? grid[a][0] : grid[0][a];
        const Cylindrical c0 = cylindrical(first, origin, axis);
        for (std::size_t b = 1; b < (along ? m : n); ++b) {
            const Cylindrical c = cylindrical(along ? grid[a][b] : grid[b][a], origin, axis);
            worst = std::max({worst, std::abs(c.height - c0.height), std::abs(c.radius - c0.radius)});
        }
    }
    return worst;
}

// The largest distance of the rows' (along) or columns' last point from their first moved by `displacement`.
double sweep_spread(const std::vector<std::vector<Vec3>>& grid, const Vec3& displacement, bool along) {
    double forward = 0, backward = 0;
    const std::size_t n = grid.size(), m = grid.front().size();
    for (std::size_t a = 0; a < (along ? n : m); ++a) {
        const Vec3& first = along ? grid[a].front() : grid.front()[a];
        const Vec3& last = along ? grid[a].back() : grid.back()[a];
        forward = std::max(forward, distance(last, first + displacement));
        backward = std::max(backward, distance(last, first - displacement));
    }
    return std::min(forward, backward);
}

}  // namespace

void require_describes(const Construction& construction, std::span<const Face> faces, std::string_view argument) {
    if (construction.get<std::monostate>() != nullptr || faces.empty()) return;
    const Checker check(faces, argument);
    const std::string_view kind = construction.kind();
    for (std::size_t index = 0; index < faces.size(); ++index) {
        const Face& face = faces[index];
        const bool planar = face.kind() == Face::Kind::planar;
        const std::vector<std::vector<Vec3>> grid = face_samples(face);
        double worst = 0;
        auto each = [&](auto&& distance_of) {
            for (const auto& row : grid)
                for (const Vec3& p : row) worst = std::max(worst, distance_of(p));
        };
        if (const auto* s = construction.get<Construction::Sphere>()) {
            require(!planar, argument, "the sphere record does not describe face " + std::to_string(index) + ": a sphere has no planar face");
            each([&](const Vec3& p) { return std::abs(distance(p, s->center) - s->radius); });
            check.require_within(worst, index, kind, "a point of it is");
        } else if (const auto* t = construction.get<Construction::Torus>()) {
            require(!planar, argument, "the torus record does not describe face " + std::to_string(index) + ": a torus has no planar face");
            each([&](const Vec3& p) {
                const Cylindrical c = cylindrical(p, t->center, t->axis);
                return std::abs(std::hypot(c.radius - t->major_radius, c.height) - t->minor_radius);
            });
            check.require_within(worst, index, kind, "a point of it is");
        } else if (construction.get<Construction::Cylinder>() != nullptr || construction.get<Construction::Cone>() != nullptr) {
            Vec3 center, axis;
            double r1 = 0, r2 = 0, h = 0;
            if (const auto* c = construction.get<Construction::Cylinder>()) center = c->center, axis = c->axis, r1 = r2 = c->radius, h = c->height;
            if (const auto* k = construction.get<Construction::Cone>()) center = k->center, axis = k->axis, r1 = k->radius1, r2 = k->radius2, h = k->height;
            each([&](const Vec3& p) {
                const Cylindrical c = cylindrical(p, center, axis);
                // Outside the slab between the end planes, or past the lateral surface's radius there: off.
                const double slab = std::max({0.0, -c.height, c.height - h});
                const double lateral = std::abs(c.radius - (r1 + (r2 - r1) * std::clamp(c.height / h, 0.0, 1.0)));
                if (planar) {
                    // A cap: at one end, within its radius.
                    const double bottom = std::abs(c.height) + std::max(0.0, c.radius - r1);
                    const double top = std::abs(c.height - h) + std::max(0.0, c.radius - r2);
                    return std::min(bottom, top);
                }
                return std::max(slab, lateral);
            });
            check.require_within(worst, index, kind, "a point of it is");
        } else if (const auto* r = construction.get<Construction::Revolution>()) {
            if (planar) {
                // A cap of a partial revolution: its plane contains the axis.
                const Plane& plane = face.plane();
                const double off = std::abs(dot(r->axis_point - plane.origin, plane.normal)) +
                                   std::abs(dot(r->axis_dir, plane.normal)) * check.size();
                check.require_within(off, index, kind, "its plane, which must contain the axis, is");
            } else {
                worst = std::min(circle_spread(grid, r->axis_point, r->axis_dir, true),
                                 circle_spread(grid, r->axis_point, r->axis_dir, false));
                check.require_within(worst, index, kind, "it is no surface of revolution about the axis: a circle of it strays");
            }
        } else if (const auto* e = construction.get<Construction::Extrusion>()) {
            const Vec3 displacement = e->direction * e->distance;
            if (planar) {
                // A cap: some other planar face's plane lies at the displacement from its plane, either way.
                const Plane& plane = face.plane();
                double nearest = std::numeric_limits<double>::infinity();
                for (std::size_t other = 0; other < faces.size(); ++other) {
                    if (other == index || faces[other].kind() != Face::Kind::planar) continue;
                    const Plane& p = faces[other].plane();
                    const double gap = dot(p.origin - plane.origin, plane.normal);
                    const double expected = dot(displacement, plane.normal);
                    nearest = std::min({nearest, std::abs(gap - expected), std::abs(gap + expected)});
                }
                check.require_within(nearest, index, kind, "no other cap lies at the displacement from it; the nearest is");
            } else {
                worst = std::min(sweep_spread(grid, displacement, true), sweep_spread(grid, displacement, false));
                check.require_within(worst, index, kind, "it is not swept by the displacement: a side strays");
            }
        }
    }
}

}  // namespace ratbez
