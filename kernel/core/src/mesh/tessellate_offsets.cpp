// The move of a vertex shared by several faces (tessellate_offsets.hpp).

#include "mesh/tessellate_offsets.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ratbez::detail {

Vec3 shared_offset(std::span<const OffsetWish> wishes, double max_offset, const EdgeBend* bend) {
    if (wishes.empty()) return {};
    // Normals within 1e-3 radians are one normal: their wishes are one offset (tessellate_offsets.hpp).
    struct Merged {
        Vec3 normal_sum;
        double lowest = 0, highest = 0;
        bool fixed = false;
        double fixed_offset = 0;
        double weight = 0, weight_lowest = 0, weight_highest = 0;  // the heaviest wish's range
        const void* face = nullptr;
        bool joint = false;  // wishes of two different faces
        Vec3 normal() const { return normal_sum / norm(normal_sum); }
        double offset() const {
            if (fixed) return fixed_offset;
            if (joint) return 0;
            if (lowest <= highest) return 0.5 * (lowest + highest);
            return std::clamp(0.5 * (lowest + highest), weight_lowest, weight_highest);
        }
    };
    std::vector<Merged> merged;
    const double same = std::cos(1e-3);
    Vec3 all_normals{};
    double all_offsets = 0;
    for (const OffsetWish& w : wishes) {
        all_normals = all_normals + w.normal;
        all_offsets += w.offset;
        auto it = std::find_if(merged.begin(), merged.end(), [&](const Merged& m) { return dot(m.normal(), w.normal) > same; });
        if (it == merged.end()) {
            merged.push_back({w.normal, w.lowest, w.highest, w.fixed, w.offset, w.weight, w.lowest, w.highest, w.face, false});
            continue;
        }
        it->normal_sum = it->normal_sum + w.normal;
        it->lowest = std::max(it->lowest, w.lowest);
        it->highest = std::min(it->highest, w.highest);
        if (w.fixed) it->fixed = true, it->fixed_offset = w.offset;
        if (w.face != it->face) it->joint = true;
        if (w.weight > it->weight) it->weight = w.weight, it->weight_lowest = w.lowest, it->weight_highest = w.highest;
    }
    auto capped = [&](const Vec3& o) {
        const double length = norm(o);
        return length > max_offset ? o * (max_offset / length) : o;
    };
    // The mean wish along the mean normal: the fallback.
    auto mean = [&] {
        const double length = norm(all_normals);
        if (!(length > 1e-9 * static_cast<double>(wishes.size()))) return Vec3{};
        return capped(all_normals / length * (all_offsets / static_cast<double>(wishes.size())));
    };
    if (merged.size() == 1) return capped(merged[0].normal() * merged[0].offset());
    if (merged.size() > 2) return {};
    // o = a n1 + b n2 with o . n1 = d1, o . n2 = d2: [1 c; c 1] (a, b) = (d1, d2), c = n1 . n2.
    const Vec3 n1 = merged[0].normal(), n2 = merged[1].normal();
    double d1 = merged[0].offset(), d2 = merged[1].offset();
    const double c = dot(n1, n2), det = 1 - c * c;
    if (!(det > 1e-12)) return mean();
    if (bend != nullptr) {
        // o . outward = d1 w1 + d2 w2: the faces' offsets move within what they accept towards the edge's
        // own wish, the larger lever first.
        const double w1 = dot(n1 - n2 * c, bend->outward) / det, w2 = dot(n2 - n1 * c, bend->outward) / det;
        double rest = bend->wanted - (d1 * w1 + d2 * w2);
        auto lean = [&](const Merged& m, double& d, double w) {
            if (m.fixed || !(std::abs(w) > 1e-6) || !(m.lowest <= m.highest)) return;
            const double moved = std::clamp(d + rest / w, m.lowest, m.highest);
            rest -= (moved - d) * w;
            d = moved;
        };
        if (std::abs(w1) >= std::abs(w2)) lean(merged[0], d1, w1), lean(merged[1], d2, w2);
        else lean(merged[1], d2, w2), lean(merged[0], d1, w1);
    }
    const Vec3 o = n1 * ((d1 - c * d2) / det) + n2 * ((d2 - c * d1) / det);
    // Too long: at a crease of less than 0.1 radians the solution runs off along the faces (the two wishes
    // nearly contradict each other), so the mean wish is taken; at a sharper crease it is shortened, which
    // keeps it in the plane of a planar face.
    if (norm(o) > max_offset && c > std::cos(0.1)) return mean();
    return capped(o);
}

}  // namespace ratbez::detail
