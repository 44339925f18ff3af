#include "spec.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/interpolation.hpp"
#include "ratbez/join.hpp"
#include "ratbez/loft.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/sweep.hpp"

namespace ratbez::spec {

bool is_valid_name(std::string_view name) {
    if (name.empty() || name.size() > 64) return false;
    const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (!letter(name.front())) return false;
    for (char c : name)
        if (!letter(c) && !(c >= '0' && c <= '9')) return false;
    return true;
}

namespace {

using nlohmann::json;

std::string join(std::initializer_list<const char*> words) {
    std::string text;
    for (const char* w : words) text += (text.empty() ? "" : ", ") + std::string(w);
    return text;
}

// Kernel argument name -> the spec field it came from (looked up by the string_view Error::argument()).
using FieldNames = std::map<std::string, std::string, std::less<>>;

// A JSON object being read: rejects unknown keys up front (so a typo is reported as the typo, not as
// the required field it was meant to be), then hands out fields with their paths.
class ObjectReader {
public:
    ObjectReader(const json& value, std::string path, std::initializer_list<const char*> allowed)
        : value_(value), path_(std::move(path)), allowed_(allowed.begin(), allowed.end()) {
        if (!value.is_object()) throw SpecError(path_.empty() ? "document" : path_, "must be a JSON object");
        for (const auto& item : value.items()) {
            bool known = false;
            for (const char* key : allowed) known = known || item.key() == key;
            if (!known) throw SpecError(child(item.key()), "unknown field (expected one of: " + join(allowed) + ")");
        }
    }

    // The document's own fields have bare names ("tolerance"), nested ones dotted paths ("shape.radius").
    // The empty key (legal JSON) has no dotted name: it is shown as [""] (found by fuzz_spec).
    std::string child(const std::string& key) const {
        if (key.empty()) return (path_.empty() ? "document" : path_) + "[\"\"]";
        return path_.empty() ? key : path_ + "." + key;
    }
    const std::string& path() const { return path_; }

    const json* optional(const char* key) const {
        const auto it = value_.find(key);
        return it == value_.end() ? nullptr : &*it;
    }
    const json& required(const char* key) const {
        const json* field = optional(key);
        if (!field) throw SpecError(child(key), "is required");
        return *field;
    }

    // Typed fields (defined below, beside the value readers they use).
    double number(const char* key) const;
    double positive(const char* key) const;
    double non_negative(const char* key) const;
    Vec3 point(const char* key) const;
    Vec3 direction(const char* key) const;
    Vec3 point_or(const char* key, Vec3 fallback) const;
    Vec3 direction_or(const char* key, Vec3 fallback) const;
    // A primitive's optional `center` and `axis`, with the kernel's defaults (the origin, +z).
    struct Placement {
        Vec3 center, axis;
    };
    Placement placement() const { return {point_or("center", {}), direction_or("axis", {0, 0, 1})}; }

    // For build(): the field a kernel Error about an argument belongs under — the field of the same name,
    // or the one `renames` gives where the kernel's name differs from the spec's ({"start", "from"}).
    using Renames = std::initializer_list<std::pair<const std::string, std::string>>;
    FieldNames fields(Renames renames = {}) const {
        FieldNames argument_to_field(renames);
        for (const char* key : allowed_) argument_to_field.emplace(key, key);
        return argument_to_field;
    }

private:
    const json& value_;
    std::string path_;
    std::vector<const char*> allowed_;
};

std::string index_path(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

double number(const json& value, const std::string& path) {
    if (!value.is_number()) throw SpecError(path, "must be a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) throw SpecError(path, "must be a finite number");
    return x;
}

double positive(const json& value, const std::string& path) {
    if (!value.is_number()) throw SpecError(path, "must be a positive number");
    const double x = number(value, path);
    if (!(x > 0)) throw SpecError(path, "must be a positive number");
    return x;
}

double non_negative(const json& value, const std::string& path) {
    if (!value.is_number()) throw SpecError(path, "must be a number >= 0");
    const double x = number(value, path);
    if (!(x >= 0)) throw SpecError(path, "must be a number >= 0");
    return x;
}

std::string text(const json& value, const std::string& path) {
    if (!value.is_string()) throw SpecError(path, "must be a string");
    return value.get<std::string>();
}

// [x, y] or [x, y, z]; 2D means z = 0.
Vec3 point(const json& value, const std::string& path) {
    if (!value.is_array() || value.size() < 2 || value.size() > 3 ||
        !std::all_of(value.begin(), value.end(), [](const json& x) { return x.is_number(); }))
        throw SpecError(path, "must be a list of 2 or 3 numbers");
    Vec3 p{number(value[0], path), number(value[1], path), value.size() == 3 ? number(value[2], path) : 0.0};
    return p;
}

Vec3 direction(const json& value, const std::string& path) {
    const Vec3 v = point(value, path);
    if (!(norm(v) > 0)) throw SpecError(path, "must be a non-zero vector");
    return v;
}

double ObjectReader::number(const char* key) const { return ::ratbez::spec::number(required(key), child(key)); }
double ObjectReader::positive(const char* key) const { return ::ratbez::spec::positive(required(key), child(key)); }
double ObjectReader::non_negative(const char* key) const {
    return ::ratbez::spec::non_negative(required(key), child(key));
}
Vec3 ObjectReader::point(const char* key) const { return ::ratbez::spec::point(required(key), child(key)); }
Vec3 ObjectReader::direction(const char* key) const { return ::ratbez::spec::direction(required(key), child(key)); }
Vec3 ObjectReader::point_or(const char* key, Vec3 fallback) const {
    const json* value = optional(key);
    return value ? ::ratbez::spec::point(*value, child(key)) : fallback;
}
Vec3 ObjectReader::direction_or(const char* key, Vec3 fallback) const {
    const json* value = optional(key);
    return value ? ::ratbez::spec::direction(*value, child(key)) : fallback;
}

std::vector<Vec3> point_list(const json& value, const std::string& path, std::size_t minimum) {
    if (!value.is_array()) throw SpecError(path, "must be a list of points");
    if (value.size() < minimum) throw SpecError(path, "must have at least " + std::to_string(minimum) + " points");
    std::vector<Vec3> points;
    points.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) points.push_back(point(value[i], index_path(path, i)));
    return points;
}

std::vector<double> number_list(const json& value, const std::string& path) {
    if (!value.is_array()) throw SpecError(path, "must be a list of numbers");
    std::vector<double> numbers;
    numbers.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) numbers.push_back(number(value[i], index_path(path, i)));
    return numbers;
}

std::vector<double> weight_list(const json& value, const std::string& path, std::size_t count) {
    std::vector<double> weights = number_list(value, path);
    if (weights.size() != count)
        throw SpecError(path, "must have one weight per point (" + std::to_string(count) + "), not " +
                                  std::to_string(weights.size()));
    for (std::size_t i = 0; i < weights.size(); ++i)
        if (!(weights[i] > 0)) throw SpecError(index_path(path, i), "must be a positive number");
    return weights;
}

// The kernel names its arguments (Error("radius", "must be greater than 0")); report that under the JSON
// path of the field the argument came from, or under the object's path when it is no field of its own.
[[noreturn]] void rethrow_kernel_error(const Error& error, const std::string& path,
                                       const FieldNames& argument_to_field) {
    if (const auto it = argument_to_field.find(error.argument()); it != argument_to_field.end())
        throw SpecError(Error(it->second, error.reason()).under(path));
    throw SpecError(path, error.what());
}

template <class Build>
auto build(const std::string& path, const FieldNames& argument_to_field, Build&& make) {
    try {
        return make();
    } catch (const SpecError&) {
        throw;
    } catch (const Error& e) {
        rethrow_kernel_error(e, path, argument_to_field);
    }
}

// The `type` of a curve or shape object, read before the object's other fields (they depend on it).
std::string type_field(const json& object, const std::string& path) {
    const auto type = object.find("type");
    if (type == object.end()) throw SpecError(path + ".type", "is required");
    return text(*type, path + ".type");
}

NurbsCurve parse_curve(const json& value, const std::string& path) {
    if (!value.is_object()) throw SpecError(path, "must be a JSON object (a curve)");
    const std::string type = type_field(value, path);

    if (type == "bezier") {
        const ObjectReader curve(value, path, {"type", "points", "weights"});
        std::vector<Vec3> points = point_list(curve.required("points"), curve.child("points"), 2);
        const json* weights = curve.optional("weights");
        return build(path, curve.fields(), [&] {
            if (!weights) return NurbsCurve::from_bezier(BezierCurve(points));
            return NurbsCurve::from_bezier(BezierCurve(points, weight_list(*weights, curve.child("weights"), points.size())));
        });
    }
    if (type == "nurbs") {
        const ObjectReader curve(value, path, {"type", "degree", "knots", "points", "weights"});
        const json& degree_value = curve.required("degree");
        if (!degree_value.is_number_integer() || degree_value.get<long long>() < 1 || degree_value.get<long long>() > 30)
            throw SpecError(curve.child("degree"), "must be an integer from 1 to 30");
        const int degree = static_cast<int>(degree_value.get<long long>());
        std::vector<double> knots = number_list(curve.required("knots"), curve.child("knots"));
        std::vector<Vec3> points = point_list(curve.required("points"), curve.child("points"), 2);
        const json* weights = curve.optional("weights");
        if (knots.size() != points.size() + static_cast<std::size_t>(degree) + 1)
            throw SpecError(curve.child("knots"), "must have len(points) + degree + 1 = " +
                                                      std::to_string(points.size() + static_cast<std::size_t>(degree) + 1) +
                                                      " values, not " + std::to_string(knots.size()));
        return build(path, curve.fields(), [&] {
            if (!weights) return NurbsCurve(degree, knots, points);
            return NurbsCurve(degree, knots, points, weight_list(*weights, curve.child("weights"), points.size()));
        });
    }
    if (type == "line") {
        const ObjectReader curve(value, path, {"type", "from", "to"});
        const Vec3 from = curve.point("from");
        const Vec3 to = curve.point("to");
        return build(path, curve.fields({{"start", "from"}, {"end", "to"}}), [&] { return line_segment(from, to); });
    }
    if (type == "arc") {
        const ObjectReader curve(value, path, {"type", "radius", "start_deg", "end_deg", "center", "normal"});
        const double radius = curve.positive("radius");
        const double start = curve.number("start_deg");
        const double end = curve.number("end_deg");
        const Vec3 center = curve.point_or("center", {});
        const Vec3 normal = curve.direction_or("normal", {0, 0, 1});
        return build(path, curve.fields(),
                     [&] { return arc(radius, start, end, center, normal); });
    }
    if (type == "circle") {
        const ObjectReader curve(value, path, {"type", "radius", "center", "normal"});
        const double radius = curve.positive("radius");
        const Vec3 center = curve.point_or("center", {});
        const Vec3 normal = curve.direction_or("normal", {0, 0, 1});
        return build(path, curve.fields(),
                     [&] { return circle(radius, center, normal); });
    }
    if (type == "interpolate") {
        // Issue 26: the curve through points (A9.1), as ratbez.interpolate takes it.
        const ObjectReader curve(value, path, {"type", "points", "degree", "parameterization", "tangents", "closed"});
        std::vector<Vec3> points = point_list(curve.required("points"), curve.child("points"), 2);
        int degree = 3;
        if (const json* d = curve.optional("degree")) {
            if (!d->is_number_integer() || d->get<long long>() < 1 || d->get<long long>() > 25)
                throw SpecError(curve.child("degree"), "must be an integer from 1 to 25");
            degree = static_cast<int>(d->get<long long>());
        }
        std::string kind = "chord";
        if (const json* k = curve.optional("parameterization")) kind = text(*k, curve.child("parameterization"));
        EndTangents tangents;
        if (const json* t = curve.optional("tangents")) {
            const std::string tangents_path = curve.child("tangents");
            if (!t->is_array() || t->size() != 2)
                throw SpecError(tangents_path, "must be [start, end], each a vector or null");
            if (!(*t)[0].is_null()) tangents.start = direction((*t)[0], index_path(tangents_path, 0));
            if (!(*t)[1].is_null()) tangents.end = direction((*t)[1], index_path(tangents_path, 1));
        }
        bool closed = false;
        if (const json* c = curve.optional("closed")) {
            if (!c->is_boolean()) throw SpecError(curve.child("closed"), "must be true or false");
            closed = c->get<bool>();
        }
        return build(path, curve.fields(),
                     [&] { return interpolate(points, degree, parse_parameterization(kind), tangents, closed); });
    }
    throw SpecError(path + ".type",
                    "unknown curve type '" + type + "' (expected bezier, nurbs, line, arc, circle or interpolate)");
}

std::vector<NurbsCurve> parse_curve_list(const json& value, const std::string& path) {
    if (!value.is_array()) throw SpecError(path, "must be a list of curves");
    if (value.empty()) throw SpecError(path, "must have at least one curve");
    std::vector<NurbsCurve> pieces;
    pieces.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) pieces.push_back(parse_curve(value[i], index_path(path, i)));
    return pieces;
}

Profile parse_profile(const json& value, const std::string& path) {
    std::vector<NurbsCurve> pieces = parse_curve_list(value, path);
    return build(path, {}, [&] { return Profile(std::move(pieces)); });
}

struct BuiltShape {
    std::string type;
    Solid solid;
};

// ---- the modelling kinds (issue 18): ruled, loft, sweep

// A path: curves joined end to end into one (join.hpp); the kernel names it "curves", the spec `path`.
NurbsCurve parse_path(const json& value, const std::string& path) {
    std::vector<NurbsCurve> pieces = parse_curve_list(value, path);
    try {
        return join(pieces);
    } catch (const Error& e) {
        const Error named = e.argument().starts_with("curves") ? e.renamed("curves", path) : e.under(path);
        throw SpecError(named.argument(), named.reason());
    }
}

// An optional true/false field (`fallback` when absent).
bool flag(const ObjectReader& shape, const char* key, bool fallback) {
    const json* value = shape.optional(key);
    if (!value) return fallback;
    if (!value->is_boolean()) throw SpecError(shape.child(key), "must be true or false");
    return value->get<bool>();
}

// The loft's kernel errors name "profiles[k]": they belong under shape.profiles[k].
FieldNames indexed_fields(const std::string& name, std::size_t count, FieldNames fields) {
    for (std::size_t k = 0; k < count; ++k) fields.emplace(index_path(name, k), index_path(name, k));
    return fields;
}

std::optional<BuiltShape> parse_modelling_shape(const std::string& type, const json& value, const std::string& path) {
    if (type == "ruled") {
        const ObjectReader shape(value, path, {"type", "profile_a", "profile_b", "align"});
        Profile a = parse_profile(shape.required("profile_a"), shape.child("profile_a"));
        Profile b = parse_profile(shape.required("profile_b"), shape.child("profile_b"));
        const bool align = flag(shape, "align", true);
        // A side surface that meets itself is about both profiles: named after the second, the one it is ruled to.
        Solid solid = build(path, shape.fields({{"profiles[0]", "profile_a"}, {"profiles[1]", "profile_b"}, {"profiles", "profile_b"}}),
                            [&] { return loft({a, b}, 1, true, align); });
        return BuiltShape{type, std::move(solid), };
    }
    if (type == "loft") {
        const ObjectReader shape(value, path, {"type", "profiles", "degree", "ruled", "align"});
        const json& list = shape.required("profiles");
        const std::string list_path = shape.child("profiles");
        if (!list.is_array() || list.size() < 2) throw SpecError(list_path, "must be a list of at least 2 profiles");
        std::vector<Profile> profiles;
        for (std::size_t k = 0; k < list.size(); ++k) profiles.push_back(parse_profile(list[k], index_path(list_path, k)));
        int degree = 3;
        if (const json* d = shape.optional("degree")) {
            if (!d->is_number_integer() || d->get<long long>() < 1 || d->get<long long>() > 10)
                throw SpecError(shape.child("degree"), "must be an integer from 1 to 10");
            degree = static_cast<int>(d->get<long long>());
        }
        const bool ruled = flag(shape, "ruled", false), align = flag(shape, "align", true);
        Solid solid = build(path, indexed_fields("profiles", profiles.size(), shape.fields()),
                            [&] { return loft(profiles, degree, ruled, align); });
        return BuiltShape{type, std::move(solid), };
    }
    if (type == "sweep") {
        const ObjectReader shape(value, path, {"type", "profile", "path", "tolerance"});
        Profile profile = parse_profile(shape.required("profile"), shape.child("profile"));
        NurbsCurve along = parse_path(shape.required("path"), shape.child("path"));
        double tolerance = 1e-6;
        if (const json* t = shape.optional("tolerance")) tolerance = positive(*t, shape.child("tolerance"));
        Solid solid = build(path, shape.fields(), [&] { return sweep(profile, along, tolerance); });
        return BuiltShape{type, std::move(solid), };
    }
    return std::nullopt;
}

BuiltShape parse_shape(const json& value, const std::string& path) {
    if (!value.is_object()) throw SpecError(path, "must be a JSON object");
    const std::string type = type_field(value, path);

    if (type == "cylinder") {
        const ObjectReader shape(value, path, {"type", "radius", "height", "center", "axis"});
        const double radius = shape.positive("radius");
        const double height = shape.positive("height");
        const auto at = shape.placement();
        return {type, build(path, shape.fields(), [&] { return cylinder(radius, height, at.center, at.axis); })};
    }
    if (type == "cone") {
        const ObjectReader shape(value, path, {"type", "radius1", "radius2", "height", "center", "axis"});
        const double radius1 = shape.non_negative("radius1");
        const double radius2 = shape.non_negative("radius2");
        const double height = shape.positive("height");
        const auto at = shape.placement();
        return {type, build(path, shape.fields(), [&] { return cone(radius1, radius2, height, at.center, at.axis); })};
    }
    if (type == "sphere") {
        const ObjectReader shape(value, path, {"type", "radius", "center"});
        const double radius = shape.positive("radius");
        const Vec3 center = shape.point_or("center", {});
        return {type, build(path, shape.fields(), [&] { return sphere(radius, center); })};
    }
    if (type == "torus") {
        const ObjectReader shape(value, path, {"type", "major_radius", "minor_radius", "center", "axis"});
        const double major = shape.positive("major_radius");
        const double minor = shape.positive("minor_radius");
        const auto at = shape.placement();
        return {type, build(path, shape.fields(), [&] { return torus(major, minor, at.center, at.axis); })};
    }
    if (type == "revolve") {
        const ObjectReader shape(value, path, {"type", "profile", "axis_point", "axis_dir", "angle"});
        Profile profile = parse_profile(shape.required("profile"), shape.child("profile"));
        const Vec3 axis_point = shape.point_or("axis_point", {});
        const Vec3 axis_dir = shape.direction_or("axis_dir", {0, 0, 1});
        double angle = 360.0;
        if (const json* a = shape.optional("angle")) {
            angle = number(*a, shape.child("angle"));
            if (!(angle > 0 && angle <= 360)) throw SpecError(shape.child("angle"), "must be in (0, 360] degrees");
        }
        return {type, build(path, shape.fields({{"axis", "axis_dir"}, {"angle_deg", "angle"}}),
                            [&] { return revolve(profile, axis_point, axis_dir, angle); })};
    }
    if (type == "extrude") {
        const ObjectReader shape(value, path, {"type", "profile", "direction", "distance"});
        Profile profile = parse_profile(shape.required("profile"), shape.child("profile"));
        const Vec3 dir = shape.direction("direction");
        const double distance = shape.positive("distance");
        return {type, build(path, shape.fields({{"displacement", "direction"}}),
                            [&] { return extrude(profile, dir, distance); })};
    }
    if (std::optional<BuiltShape> built = parse_modelling_shape(type, value, path)) return std::move(*built);
    throw SpecError(path + ".type", "unknown shape type '" + type +
                                        "' (expected cylinder, cone, sphere, torus, revolve, extrude, ruled, loft or sweep)");
}

// nlohmann's messages start with "[json.exception.parse_error.101] "; the reader needs only the rest.
std::string json_message(const json::exception& e) {
    std::string message = e.what();
    if (const auto close = message.find("] "); !message.empty() && message.front() == '[' && close != std::string::npos)
        message.erase(0, close + 2);
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    return message;
}

}  // namespace

ShapeSpec parse_spec(std::string_view json_text, const std::string& fallback_name) {
    if (json_text.size() > max_spec_bytes)
        throw SpecError("document", "has " + std::to_string(json_text.size()) + " bytes, above the limit " +
                                        std::to_string(max_spec_bytes) + " for a spec");
    // The JSON parser takes a NUL byte for the end of the text, so whatever followed one went unread (a spec
    // with garbage after "}\0" was accepted, issue 29): JSON text has no NUL outside strings, nor in them
    // unescaped, so any NUL refuses the document.
    if (const std::size_t nul = json_text.find('\0'); nul != std::string_view::npos)
        throw SpecError("document", "not valid JSON: a NUL byte at offset " + std::to_string(nul) + " (JSON text has none)");
    json document;
    try {
        // Checked while parsing, before the document grows with them (issue 14): the nesting depth (30 MB of
        // '[' took 2.3 GB) and keys repeated in one object (the last one silently won).
        std::vector<std::set<std::string>> keys;  // of the objects open at this point
        const json::parser_callback_t check = [&](int depth, json::parse_event_t event, json& parsed) {
            if (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start) {
                if (depth >= max_json_depth)
                    throw SpecError("document", "nests objects and arrays deeper than the limit " +
                                                    std::to_string(max_json_depth));
                if (event == json::parse_event_t::object_start) keys.emplace_back();
            } else if (event == json::parse_event_t::object_end) {
                keys.pop_back();
            } else if (event == json::parse_event_t::key && !keys.back().insert(parsed.get<std::string>()).second) {
                throw SpecError("document", "the key \"" + parsed.get<std::string>() + "\" appears twice in one object");
            }
            return true;
        };
        document = json::parse(json_text.begin(), json_text.end(), check);
    } catch (const json::exception& e) {
        // parse_error for malformed text, out_of_range for a number that overflows a double (1e400).
        throw SpecError("document", "not valid JSON: " + json_message(e));
    }
    try {
        if (!document.is_object()) throw SpecError("document", "must be a JSON object with a \"shape\"");
        const ObjectReader top(document, "", {"name", "description", "tolerance", "tessellation_angle", "color", "shape"});
        std::string name = is_valid_name(fallback_name) ? fallback_name : "shape";
        if (const json* n = top.optional("name")) {
            name = text(*n, "name");
            if (!is_valid_name(name))
                throw SpecError("name", "must be 1 to 64 letters, digits or _, not starting with a digit");
        }
        std::string description;
        if (const json* d = top.optional("description")) description = text(*d, "description");
        std::optional<double> tolerance;
        if (const json* t = top.optional("tolerance")) tolerance = positive(*t, "tolerance");
        std::optional<double> angle;
        if (const json* a = top.optional("tessellation_angle")) {
            angle = number(*a, "tessellation_angle");
            if (!(*angle > 0 && *angle < 180)) throw SpecError("tessellation_angle", "must be in (0, 180) degrees");
        }
        std::optional<std::string> color;  // its form ("#rrggbb") is checked where it is used (exporter::parse_color)
        if (const json* c = top.optional("color")) color = text(*c, "color");
        const json* shape = top.optional("shape");
        if (!shape) throw SpecError("shape", "is required");
        BuiltShape built = parse_shape(*shape, "shape");
        return ShapeSpec{std::move(name), std::move(description), std::move(built.type), tolerance, angle,
                         std::move(built.solid), top.optional("name") != nullptr, std::move(color)};
    } catch (const json::exception& e) {
        // Unreachable for a well-typed reader; kept so that no JSON library error escapes as another type.
        throw SpecError("document", json_message(e));
    }
}

ShapeSpec load_spec(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SpecError(path, "cannot open the file");
    // At most one byte past the limit is read: /dev/zero or a huge file is refused, not read into memory.
    std::string text(max_spec_bytes + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) throw SpecError(path, "cannot read the file");
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_spec_bytes)
        throw SpecError(path, "has more than " + std::to_string(max_spec_bytes) + " bytes, the limit for a spec");
    try {
        return parse_spec(text, std::filesystem::path(path).stem().string());
    } catch (const SpecError& e) {
        if (e.path() == "document") throw SpecError(path, e.reason());
        throw;
    }
}

}  // namespace ratbez::spec
