#include "ratbez/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/mesh_topology.hpp"

namespace ratbez {
namespace {

// volume() and area() read the vertices a triangle names: an index past the table is an Error, not a
// read out of bounds (meshes come from files and users too, not only from tessellate).
void require_valid_indices(const Mesh& mesh) {
    const std::size_t count = mesh.vertices.size();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (const std::uint32_t index : mesh.triangles[t])
            if (index >= count)  // not require(): the message is built only on failure
                throw Error("mesh", "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(index) +
                            " but there are only " + std::to_string(count) + " vertices");
}

// The vertices in a frame of their own: relative to the centre of their box and in units of 2^exponent (the
// power of two of the box's half size), so that the triple products of volume() and the cross products of
// area() are of order 1 wherever the mesh lies and however large or small it is. At the origin's frame a
// closed mesh of size 1 at 1e6 lost its volume to cancellation (a torus read 97.7 for 39.5, issue 29) and
// one with coordinates of 1e308 overflowed to NaN. The sums are scaled back exactly (2^(3 exponent) and
// 2^(2 exponent)); a result past the double range is an Error.
struct LocalVertices {
    std::vector<Vec3> points;
    int exponent = 0;
};

LocalVertices local_vertices(const Mesh& mesh) {
    LocalVertices local;
    if (mesh.vertices.empty()) return local;
    Vec3 low = mesh.vertices.front(), high = low;
    for (const Vec3& v : mesh.vertices) {
        low = {std::min(low.x, v.x), std::min(low.y, v.y), std::min(low.z, v.z)};
        high = {std::max(high.x, v.x), std::max(high.y, v.y), std::max(high.z, v.z)};
    }
    require(is_finite(low) && is_finite(high), "mesh", "has a vertex with a coordinate that is not a finite number");
    // Halves first: neither the centre nor the half extent overflows for coordinates near the double limit.
    const Vec3 centre = low * 0.5 + high * 0.5;
    const double half = std::max({high.x * 0.5 - low.x * 0.5, high.y * 0.5 - low.y * 0.5, high.z * 0.5 - low.z * 0.5});
    local.exponent = half > 0 ? std::ilogb(half) + 1 : 0;
    const auto scaled = [&](const Vec3& p) {
        return Vec3{std::ldexp(p.x, -local.exponent), std::ldexp(p.y, -local.exponent), std::ldexp(p.z, -local.exponent)};
    };
    const Vec3 origin = scaled(centre);
    local.points.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) local.points.push_back(scaled(v) - origin);
    return local;
}

}  // namespace

bool Mesh::is_closed() const {
    // Each directed edge appears exactly once and its reverse exactly once (mesh_topology.hpp).
    for (const auto& t : triangles)
        for (const std::uint32_t v : t)
            if (v >= vertices.size()) return false;
    if (triangles.empty()) return false;
    return mesh_topology(*this).watertight();
}

double Mesh::volume() const {
    require_valid_indices(*this);
    const LocalVertices local = local_vertices(*this);
    const std::vector<Vec3>& p = local.points;
    detail::CompensatedSum six_volume;  // millions of triangles: naive summation would cost digits
    for (const auto& t : triangles) six_volume.add(dot(p[t[0]], cross(p[t[1]], p[t[2]])));
    const double volume = std::ldexp(six_volume.value() / 6.0, 3 * local.exponent);
    require(std::isfinite(volume), "mesh", "its volume is beyond the double range (the mesh is too large to measure)");
    return volume;
}

double Mesh::area() const {
    require_valid_indices(*this);
    const LocalVertices local = local_vertices(*this);
    const std::vector<Vec3>& p = local.points;
    detail::CompensatedSum twice_area;
    for (const auto& t : triangles) twice_area.add(norm(cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]])));
    const double area = std::ldexp(twice_area.value() / 2.0, 2 * local.exponent);
    require(std::isfinite(area), "mesh", "its area is beyond the double range (the mesh is too large to measure)");
    return area;
}

bool is_flat_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double longest = std::max({norm(b - a), norm(c - b), norm(a - c)});
    return norm(cross(b - a, c - a)) <= 1e-9 * longest * longest;
}

}  // namespace ratbez
