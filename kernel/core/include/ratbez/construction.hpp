#pragma once
// What a Solid was built as (Solid::construction()): the primitive or sweep and the parameters it was
// given. The Solid keeps the record so that nothing downstream re-derives "this is a sphere of radius r":
// the OpenCASCADE check compares the faces with the analytic surface it names, the CLI and Python report
// it, and the exact volume and area come in closed form where one exists (cylinder, cone, sphere, torus).

#include <concepts>
#include <optional>
#include <string_view>
#include <utility>
#include <variant>

#include "ratbez/vec.hpp"

namespace ratbez {

class Construction {
public:
    // The parameters of each kind carry the names of the arguments of the function that builds it
    // (primitives.hpp, revolve.hpp, extrude.hpp), so a record reads like the call; axes and directions
    // are stored as unit vectors.
    struct Cylinder {
        Vec3 center;  // the base center
        Vec3 axis{0, 0, 1};
        double radius = 0, height = 0;
        friend bool operator==(const Cylinder&, const Cylinder&) = default;
    };
    struct Cone {
        Vec3 center;  // the base center
        Vec3 axis{0, 0, 1};
        double radius1 = 0, radius2 = 0, height = 0;  // radius1 at the base; either may be 0 (an apex)
        friend bool operator==(const Cone&, const Cone&) = default;
    };
    struct Sphere {
        Vec3 center;
        double radius = 0;
        friend bool operator==(const Sphere&, const Sphere&) = default;
    };
    struct Torus {
        Vec3 center;
        Vec3 axis{0, 0, 1};
        double major_radius = 0, minor_radius = 0;
        friend bool operator==(const Torus&, const Torus&) = default;
    };
    struct Revolution {  // of a general profile (the profile itself is the faces' business)
        Vec3 axis_point;
        Vec3 axis_dir{0, 0, 1};
        double angle_deg = 360;
        friend bool operator==(const Revolution&, const Revolution&) = default;
    };
    struct Extrusion {  // of a general closed profile
        Vec3 direction{0, 0, 1};
        double distance = 0;
        friend bool operator==(const Extrusion&, const Extrusion&) = default;
    };
    // std::monostate: none, a Solid assembled directly from faces.
    using Parameters = std::variant<std::monostate, Cylinder, Cone, Sphere, Torus, Revolution, Extrusion>;

    Construction() = default;
    // Implicit, so that a builder writes Solid(faces, Construction::Sphere{center, radius}). Validated as
    // the builders validate their arguments (finite numbers, positive sizes, 0 < angle <= 360; a zero axis
    // is refused, any other normalised), throwing Error naming "construction.<field>". Whether the record
    // describes the faces is the builder's promise; occt::check measures it against OCCT's surfaces.
    template <class Kind>
        requires std::constructible_from<Parameters, Kind>
    Construction(Kind parameters) : parameters_(validated(Parameters(std::move(parameters)))) {}

    const Parameters& parameters() const { return parameters_; }
    bool operator==(const Construction&) const = default;
    // The parameters when the record is of that kind, else nullptr: construction.get<Construction::Sphere>().
    template <class Kind>
    const Kind* get() const {
        return std::get_if<Kind>(&parameters_);
    }
    // "none", "cylinder", "cone", "sphere", "torus", "revolution" or "extrusion".
    std::string_view kind() const;

    // The closed forms of the primitives (a cone's lateral area is π (r1 + r2) times its slant height;
    // a torus's volume and area are Pappus's 2π R times the tube's disc and circle); nullopt for a
    // revolution or extrusion of a general profile, and for none.
    std::optional<double> exact_volume() const;
    std::optional<double> exact_area() const;

private:
    static Parameters validated(Parameters parameters);

    Parameters parameters_;
};

}  // namespace ratbez
