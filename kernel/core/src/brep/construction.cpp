#include "ratbez/construction.hpp"

#include <cmath>
#include <iterator>
#include <numbers>

#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez {

namespace {

constexpr double pi = std::numbers::pi;

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
    if (auto* c = std::get_if<Cylinder>(&parameters)) {
        place(c->center, c->axis);
        require_positive(c->radius, "construction.radius");
        require_positive(c->height, "construction.height");
    } else if (auto* k = std::get_if<Cone>(&parameters)) {
        place(k->center, k->axis);
        require_non_negative(k->radius1, "construction.radius1");
        require_non_negative(k->radius2, "construction.radius2");
        require(k->radius1 > 0 || k->radius2 > 0, "construction.radius1", "radius1 and radius2 cannot both be 0");
        require_positive(k->height, "construction.height");
    } else if (auto* s = std::get_if<Sphere>(&parameters)) {
        require_point(s->center, "construction.center");
        require_positive(s->radius, "construction.radius");
    } else if (auto* t = std::get_if<Torus>(&parameters)) {
        place(t->center, t->axis);
        require_positive(t->minor_radius, "construction.minor_radius");
        require(t->minor_radius < t->major_radius && std::isfinite(t->major_radius), "construction.minor_radius",
                "must be less than a finite major_radius");
    } else if (auto* r = std::get_if<Revolution>(&parameters)) {
        require_point(r->axis_point, "construction.axis_point");
        r->axis_dir = unit(r->axis_dir, "construction.axis_dir");
        require(std::isfinite(r->angle_deg) && r->angle_deg > 0 && r->angle_deg <= 360, "construction.angle_deg",
                "must be in (0, 360] degrees");
    } else if (auto* e = std::get_if<Extrusion>(&parameters)) {
        e->direction = unit(e->direction, "construction.direction");
        require_positive(e->distance, "construction.distance");
    }
    return parameters;
}

std::string_view Construction::kind() const {
    constexpr std::string_view names[] = {"none", "cylinder", "cone", "sphere", "torus", "revolution", "extrusion"};
    static_assert(std::size(names) == std::variant_size_v<Parameters>);
    return names[parameters_.index()];
}

std::optional<double> Construction::exact_volume() const {
    if (const auto* c = get<Cylinder>()) return pi * c->radius * c->radius * c->height;
    if (const auto* k = get<Cone>()) {
        const double a = k->radius1, b = k->radius2;
        return pi * k->height * (a * a + a * b + b * b) / 3;
    }
    if (const auto* s = get<Sphere>()) return 4 * pi * s->radius * s->radius * s->radius / 3;
    if (const auto* t = get<Torus>()) return 2 * pi * pi * t->major_radius * t->minor_radius * t->minor_radius;
    return std::nullopt;
}

std::optional<double> Construction::exact_area() const {
    if (const auto* c = get<Cylinder>()) return 2 * pi * c->radius * (c->radius + c->height);
    if (const auto* k = get<Cone>()) {
        const double a = k->radius1, b = k->radius2;
        return pi * ((a + b) * std::hypot(k->height, a - b) + a * a + b * b);  // lateral: (a + b) π times the slant
    }
    if (const auto* s = get<Sphere>()) return 4 * pi * s->radius * s->radius;
    if (const auto* t = get<Torus>()) return 4 * pi * pi * t->major_radius * t->minor_radius;
    return std::nullopt;
}

}  // namespace ratbez
