// Point-to-mesh distance (triangle_grid.hpp).

#include "mesh/triangle_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ratbez::detail {

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double length2 = dot(ab, ab);
    const double f = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return distance(p, a + ab * f);
}

double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return distance(p, a);
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return distance(p, b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return distance(p, a + ab * (d1 / (d1 - d3)));
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return distance(p, c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return distance(p, a + ac * (d2 / (d2 - d6)));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return distance(p, b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    const double denominator = va + vb + vc;
    if (!(std::abs(denominator) > 0)) return std::min({distance(p, a), distance(p, b), distance(p, c)});
    return distance(p, a + ab * (vb / denominator) + ac * (vc / denominator));
}

TriangleGrid::TriangleGrid(const Mesh& mesh) : mesh_(mesh) {
    lo_ = hi_ = mesh.vertices[mesh.triangles.front()[0]];
    double edges = 0;
    for (const auto& t : mesh.triangles)
        for (std::size_t k = 0; k < 3; ++k) {
            const Vec3& p = mesh.vertices[t[k]];
            lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y), std::min(lo_.z, p.z)};
            hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y), std::max(hi_.z, p.z)};
            edges += ratbez::distance(p, mesh.vertices[t[(k + 1) % 3]]);
        }
    // Cells about a mean edge wide (at most 512 along the longest side): a few triangles each.
    const double extent = std::max({hi_.x - lo_.x, hi_.y - lo_.y, hi_.z - lo_.z, 1e-300});
    cell_ = std::max(edges / (3.0 * static_cast<double>(mesh.triangles.size())), extent / 512);
    for (int a = 0; a < 3; ++a) dims_[a] = 1 + static_cast<int>(((&hi_.x)[a] - (&lo_.x)[a]) / cell_);
    const std::size_t cells = static_cast<std::size_t>(dims_[0]) * static_cast<std::size_t>(dims_[1]) *
                              static_cast<std::size_t>(dims_[2]);
    // Counting sort of (cell, triangle) pairs: every cell a triangle's box overlaps lists it.
    auto for_each_cell = [&](const auto& t, auto&& visit) {
        Vec3 a = mesh.vertices[t[0]], b = a;
        for (std::size_t k = 1; k < 3; ++k) {
            const Vec3& p = mesh.vertices[t[k]];
            a = {std::min(a.x, p.x), std::min(a.y, p.y), std::min(a.z, p.z)};
            b = {std::max(b.x, p.x), std::max(b.y, p.y), std::max(b.z, p.z)};
        }
        const auto ca = cell_of(a), cb = cell_of(b);
        for (int x = ca[0]; x <= cb[0]; ++x)
            for (int y = ca[1]; y <= cb[1]; ++y)
                for (int z = ca[2]; z <= cb[2]; ++z) visit(flat(x, y, z));
    };
    start_.assign(cells + 1, 0);
    for (const auto& t : mesh.triangles) for_each_cell(t, [&](std::size_t c) { ++start_[c + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    order_.resize(start_.back());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
        for_each_cell(mesh.triangles[k], [&](std::size_t c) { order_[fill[c]++] = static_cast<std::uint32_t>(k); });
}

std::array<int, 3> TriangleGrid::cell_of(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int k = 0; k < 3; ++k)
        c[k] = std::clamp(static_cast<int>(std::floor(((&p.x)[k] - (&lo_.x)[k]) / cell_)), 0, dims_[k] - 1);
    return c;
}

double TriangleGrid::distance(const Vec3& p) const {
    const double reach = 4 * (norm(hi_ - lo_) + ratbez::distance(p, 0.5 * (lo_ + hi_)) + cell_);
    for (double r = 0.5 * cell_;; r *= 2) {
        std::array<int, 3> a{}, b{};
        for (int k = 0; k < 3; ++k) {
            a[k] = std::clamp(static_cast<int>(std::floor(((&p.x)[k] - r - (&lo_.x)[k]) / cell_)), 0, dims_[k] - 1);
            b[k] = std::clamp(static_cast<int>(std::floor(((&p.x)[k] + r - (&lo_.x)[k]) / cell_)), 0, dims_[k] - 1);
        }
        double best = std::numeric_limits<double>::infinity();
        for (int x = a[0]; x <= b[0]; ++x)
            for (int y = a[1]; y <= b[1]; ++y)
                for (int z = a[2]; z <= b[2]; ++z) {
                    const std::size_t c = flat(x, y, z);
                    for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
                        const auto& t = mesh_.triangles[order_[k]];
                        best = std::min(best, point_triangle_distance(p, mesh_.vertices[t[0]], mesh_.vertices[t[1]],
                                                                      mesh_.vertices[t[2]]));
                    }
                }
        // Every triangle within r of p overlaps the box searched, so a result within r is the nearest.
        if (best <= r || r > reach) return best;
    }
}

}  // namespace ratbez::detail
