#include "ratbez/construction.hpp"

#include <cmath>
#include <iterator>
#include <numbers>

#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez {

namespace {

constexpr double pi = std::numbers::pi;

// std::visit with one lambda per kind.
template <class... Visitors>
struct Overloaded : Visitors... {
    using Visitors::operator()...;
};
template <class... Visitors>
Overloaded(Visitors...) -> Overloaded<Visitors...>;  // clang 14 (the fuzz build) lacks C++20's aggregate deduction

void require_point(const Vec3& point, const char* argument) {
    require(is_finite(point), argument, "must have finite coordinates");
}

// frame_from_axis's validation and normalisation: finite, not zero.
Vec3 unit(const Vec3& axis, const char* argument) { return frame_from_axis({}, axis, argument).z_axis; }

// The center and axis of a cylinder, cone or torus.
void place(const Vec3& center, Vec3& axis) {
    require_point(center, "construction.center");
    axis = unit(axis, "construction.axis");
}

void require_positive(double value, const char* argument) {
    require(std::isfinite(value) && value > 0, argument, "must be a finite number greater than 0");
}

void require_non_negative(double value, const char* argument) {
    require(std::isfinite(value) && value >= 0, argument, "must be a finite number at least 0");
}

}  // namespace

Construction::Parameters Construction::validated(Parameters parameters) {
    std::visit(Overloaded{
                   [](std::monostate) {},
                   [](Cylinder& c) {
                       place(c.center, c.axis);
                       require_positive(c.radius, "construction.radius");
                       require_positive(c.height, "construction.height");
                   },
                   [](Cone& c) {
                       place(c.center, c.axis);
                       require_non_negative(c.radius1, "construction.radius1");
                       require_non_negative(c.radius2, "construction.radius2");
                       require(c.radius1 > 0 || c.radius2 > 0, "construction.radius1", "radius1 and radius2 cannot both be 0");
                       require_positive(c.height, "construction.height");
                   },
                   [](Sphere& s) {
                       require_point(s.center, "construction.center");
                       require_positive(s.radius, "construction.radius");
                   },
                   [](Torus& t) {
                       place(t.center, t.axis);
                       require_positive(t.minor_radius, "construction.minor_radius");  // major_radius: finite and greater
                       require(t.minor_radius < t.major_radius && std::isfinite(t.major_radius), "construction.minor_radius",
                               "must be less than a finite major_radius");
                   },
                   [](Revolution& r) {
                       require_point(r.axis_point, "construction.axis_point");
                       r.axis_dir = unit(r.axis_dir, "construction.axis_dir");
                       require(std::isfinite(r.angle_deg) && r.angle_deg > 0 && r.angle_deg <= 360,
                               "construction.angle_deg", "must be in (0, 360] degrees");
                   },
                   [](Extrusion& e) {
                       e.direction = unit(e.direction, "construction.direction");
                       require_positive(e.distance, "construction.distance");
                   },
               },
               parameters);
    return parameters;
}

std::string_view Construction::kind() const {
    constexpr std::string_view names[] = {"none", "cylinder", "cone", "sphere", "torus", "revolution", "extrusion"};
    static_assert(std::size(names) == std::variant_size_v<Parameters>);
    return names[parameters_.index()];
}

std::optional<double> Construction::exact_volume() const {
    return std::visit(Overloaded{
                          [](const Cylinder& c) -> std::optional<double> { return pi * c.radius * c.radius * c.height; },
                          [](const Cone& c) -> std::optional<double> {
                              return pi * c.height * (c.radius1 * c.radius1 + c.radius1 * c.radius2 + c.radius2 * c.radius2) / 3;
                          },
                          [](const Sphere& s) -> std::optional<double> { return 4 * pi * s.radius * s.radius * s.radius / 3; },
                          [](const Torus& t) -> std::optional<double> {
                              return 2 * pi * pi * t.major_radius * t.minor_radius * t.minor_radius;
                          },
                          [](const auto&) -> std::optional<double> { return std::nullopt; },
                      },
                      parameters_);
}

std::optional<double> Construction::exact_area() const {
    return std::visit(Overloaded{
                          [](const Cylinder& c) -> std::optional<double> { return 2 * pi * c.radius * (c.radius + c.height); },
                          [](const Cone& c) -> std::optional<double> {
                              const double slant = std::hypot(c.height, c.radius1 - c.radius2);
                              return pi * ((c.radius1 + c.radius2) * slant + c.radius1 * c.radius1 + c.radius2 * c.radius2);
                          },
                          [](const Sphere& s) -> std::optional<double> { return 4 * pi * s.radius * s.radius; },
                          [](const Torus& t) -> std::optional<double> { return 4 * pi * pi * t.major_radius * t.minor_radius; },
                          [](const auto&) -> std::optional<double> { return std::nullopt; },
                      },
                      parameters_);
}

}  // namespace ratbez
