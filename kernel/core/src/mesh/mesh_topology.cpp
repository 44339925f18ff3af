#include "ratbez/mesh_topology.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "ratbez/error.hpp"

namespace ratbez {
namespace {

// One triangle seen from one of its vertices v: the triangle (v, next, previous) in its own orientation,
// so it uses the directed edges v -> next and previous -> v.
struct Corner {
    std::uint32_t next, previous;
};

// The triangles around each vertex as compressed rows: the corners of vertex v are
// corners[first[v]] .. corners[first[v + 1] - 1]. Degenerate triangles are left out.
struct Stars {
    std::vector<std::size_t> first;
    std::vector<Corner> corners;
};

Stars gather_stars(const Mesh& mesh, std::size_t& degenerate) {
    const std::size_t n = mesh.vertices.size();
    const auto is_degenerate = [](const std::array<std::uint32_t, 3>& t) {
        return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    };
    Stars stars;
    stars.first.assign(n + 1, 0);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& triangle = mesh.triangles[t];
        for (const std::uint32_t v : triangle)
            if (v >= n)
                throw Error("mesh", "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
                                        " but there are only " + std::to_string(n) + " vertices");
        if (is_degenerate(triangle)) {
            ++degenerate;
            continue;
        }
        for (const std::uint32_t v : triangle) ++stars.first[v + 1];
    }
    std::partial_sum(stars.first.begin(), stars.first.end(), stars.first.begin());
    stars.corners.resize(stars.first.back());
    std::vector<std::size_t> cursor(stars.first.begin(), stars.first.end() - 1);
    for (const auto& t : mesh.triangles) {
        if (is_degenerate(t)) continue;
        for (std::size_t k = 0; k < 3; ++k) stars.corners[cursor[t[k]]++] = Corner{t[(k + 1) % 3], t[(k + 2) % 3]};
    }
    return stars;
}

// Union-find over the corners of one star, with path halving.
std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

MeshTopology mesh_topology(const Mesh& mesh, const Progress& progress) {
    MeshTopology result;
    const Stars stars = gather_stars(mesh, result.degenerate_triangles);
    const std::size_t n = mesh.vertices.size();
    constexpr std::size_t kVerticesPerPoll = std::size_t{1} << 16;

    // A neighbour w of v as one corner of v's star sees it: across the edge v -> w (outgoing) or w -> v.
    struct Neighbour {
        std::uint32_t vertex;
        bool outgoing;
        std::size_t corner;  // index within the star
    };
    std::vector<Neighbour> neighbours;
    std::vector<std::size_t> parent;
    for (std::size_t v = 0; v < n; ++v) {
        if (progress && v % kVerticesPerPoll == 0) progress(static_cast<double>(v) / static_cast<double>(n));
        const std::size_t begin = stars.first[v], size = stars.first[v + 1] - begin;
        if (size == 0) continue;
        neighbours.clear();
        for (std::size_t c = 0; c < size; ++c) {
            const Corner& corner = stars.corners[begin + c];
            neighbours.push_back({corner.next, true, c});
            neighbours.push_back({corner.previous, false, c});
        }
        std::sort(neighbours.begin(), neighbours.end(), [](const Neighbour& a, const Neighbour& b) {
            return a.vertex != b.vertex ? a.vertex < b.vertex : a.outgoing < b.outgoing;
        });
        parent.resize(size);
        std::iota(parent.begin(), parent.end(), std::size_t{0});
        std::size_t fans = size;
        // Each run of one neighbour w: the triangles on the edge {v, w}.
        for (std::size_t i = 0; i < neighbours.size();) {
            std::size_t j = i, outgoing = 0;
            for (; j < neighbours.size() && neighbours[j].vertex == neighbours[i].vertex; ++j) {
                outgoing += neighbours[j].outgoing;
                // Triangles that share an edge at v belong to one fan.
                const std::size_t a = root(parent, neighbours[i].corner), b = root(parent, neighbours[j].corner);
                if (a != b) parent[b] = a, --fans;
            }
            const std::size_t uses = j - i;
            if (outgoing > 1) result.repeated_edges += outgoing - 1;  // each directed edge counted at its start
            if (neighbours[i].vertex > v) {                           // each undirected edge at its smaller end
                if (uses == 1) ++result.border_edges;
                if (uses > 2) ++result.non_manifold_edges;
            }
            if ((uses != 2 || outgoing != 1) && !result.defective_edge) {
                const auto a = static_cast<std::uint32_t>(v), b = neighbours[i].vertex;
                result.defective_edge = std::array{std::min(a, b), std::max(a, b)};
            }
            i = j;
        }
        if (fans > 1) ++result.singular_vertices;
    }
    if (progress) progress(1.0);
    return result;
}

}  // namespace ratbez
