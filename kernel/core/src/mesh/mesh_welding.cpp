#include "ratbez/mesh_welding.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <vector>

#include "ratbez/error.hpp"

namespace ratbez {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// Marks the triangles that come in pairs with the same corners once each way round: a triangle's corners rotated
// to start at the smallest index, the other way round the last two swap.
void mark_cancelling_pairs(const std::vector<Triangle>& triangles, std::vector<bool>& dropped) {
    struct Keyed {
        Triangle corners;
        bool ascending;
        std::size_t index;
    };
    std::vector<Keyed> keyed;
    keyed.reserve(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        if (dropped[t]) continue;
        const Triangle& tri = triangles[t];
        const auto first = static_cast<std::size_t>(std::min_element(tri.begin(), tri.end()) - tri.begin());
        const std::uint32_t x = tri[(first + 1) % 3], y = tri[(first + 2) % 3];
        keyed.push_back({{tri[first], std::min(x, y), std::max(x, y)}, x < y, t});
    }
    std::sort(keyed.begin(), keyed.end(),
              [](const Keyed& a, const Keyed& b) { return std::tie(a.corners, a.ascending, a.index) < std::tie(b.corners, b.ascending, b.index); });
    for (std::size_t begin = 0, end = 0; begin < keyed.size(); begin = end) {
        std::size_t descending = 0;
        while (end < keyed.size() && keyed[end].corners == keyed[begin].corners) descending += !keyed[end++].ascending;
        const std::size_t pairs = std::min(descending, end - begin - descending);
        for (std::size_t k = 0; k < pairs; ++k) dropped[keyed[begin + k].index] = dropped[keyed[begin + descending + k].index] = true;
    }
}

}  // namespace

std::vector<std::uint32_t> first_at_same_place(const std::vector<Vec3>& vertices) {
    std::vector<std::uint32_t> order(vertices.size()), first(vertices.size());
    std::iota(order.begin(), order.end(), std::uint32_t{0});
    const auto place = [&](std::uint32_t i) { return std::tie(vertices[i].x, vertices[i].y, vertices[i].z); };
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return place(a) < place(b); });
    for (std::size_t k = 0; k < order.size(); ++k)
        first[order[k]] = k > 0 && place(order[k]) == place(order[k - 1]) ? first[order[k - 1]] : order[k];
    return first;
}

Mesh welded(const Mesh& mesh, OppositePairs pairs) {
    for (const Triangle& tri : mesh.triangles)
        for (const std::uint32_t v : tri)
            require(v < mesh.vertices.size(), "mesh", "a triangle refers to a vertex past the table");
    const std::vector<std::uint32_t> first = first_at_same_place(mesh.vertices);
    std::vector<Triangle> triangles;
    triangles.reserve(mesh.triangles.size());
    std::vector<bool> dropped;
    for (const Triangle& tri : mesh.triangles) {
        const Triangle moved{first[tri[0]], first[tri[1]], first[tri[2]]};
        triangles.push_back(moved);
        dropped.push_back(moved[0] == moved[1] || moved[1] == moved[2] || moved[2] == moved[0]);
    }
    if (pairs == OppositePairs::dropped) mark_cancelling_pairs(triangles, dropped);
    Mesh result;
    std::vector<std::uint32_t> renumbered(mesh.vertices.size(), 0);
    std::vector<bool> named(mesh.vertices.size(), false);
    for (std::size_t t = 0; t < triangles.size(); ++t)
        if (!dropped[t])
            for (const std::uint32_t v : triangles[t]) named[v] = true;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        if (named[v]) {
            renumbered[v] = static_cast<std::uint32_t>(result.vertices.size());
            result.vertices.push_back(mesh.vertices[v]);
        }
    for (std::size_t t = 0; t < triangles.size(); ++t)
        if (!dropped[t]) result.triangles.push_back({renumbered[triangles[t][0]], renumbered[triangles[t][1]], renumbered[triangles[t][2]]});
    return result;
}

}  // namespace ratbez
