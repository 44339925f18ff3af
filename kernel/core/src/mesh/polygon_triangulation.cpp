#include "mesh/polygon_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "ratbez/error.hpp"

namespace ratbez::detail {
namespace {

double cross(const Point2& o, const Point2& a, const Point2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double squared_length(const Point2& a, const Point2& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return dx * dx + dy * dy;
}

bool same_point(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }

// A node of the circular doubly linked polygon being clipped; `vertex` indexes the input points.
// Bridges duplicate a vertex, so two nodes may carry the same vertex.
struct Node {
    std::size_t vertex = 0;
    std::size_t prev = 0, next = 0;
    bool active = true;
};

class EarClipper {
public:
    explicit EarClipper(std::vector<Point2> points) : points_(std::move(points)) {
        double min_x = std::numeric_limits<double>::max(), min_y = min_x, max_x = -min_x, max_y = -min_x;
        for (const Point2& p : points_) {
            min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
            min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
        }
        const double extent = std::max(max_x - min_x, max_y - min_y);
        // Twice-area threshold below which three points count as collinear: relative to the polygon's size,
        // well above the rounding of the cross products, far below any triangle a tolerance would produce.
        collinear_ = 1e-13 * extent * extent;
    }

    // Appends a loop (vertex indices into the points) as a circular list; returns its first node.
    std::size_t add_loop(const std::vector<std::size_t>& vertices) {
        const std::size_t first = nodes_.size();
        for (std::size_t k = 0; k < vertices.size(); ++k) {
            Node node;
            node.vertex = vertices[k];
            node.prev = first + (k + vertices.size() - 1) % vertices.size();
            node.next = first + (k + 1) % vertices.size();
            nodes_.push_back(node);
        }
        return first;
    }

    // Eberly §3: joins a hole (clockwise, given by any of its nodes) to the outer polygon by the bridge
    // from the hole's rightmost vertex M to a mutually visible outer vertex P.
    void bridge_hole(std::size_t outer_start, std::size_t hole_start) {
        std::size_t m = hole_start;
        for (std::size_t n = nodes_[hole_start].next; n != hole_start; n = nodes_[n].next)
            if (pt(n).x > pt(m).x || (pt(n).x == pt(m).x && pt(n).y < pt(m).y)) m = n;
        const Point2 mp = pt(m);

        // The nearest edge hit by the ray from M in +x.
        double best_x = std::numeric_limits<double>::infinity();
        std::size_t hit = outer_start;
        bool found = false;
        std::size_t n = outer_start;
        do {
            const std::size_t nx = nodes_[n].next;
            const Point2 a = pt(n), b = pt(nx);
            if ((a.y <= mp.y && b.y > mp.y) || (b.y <= mp.y && a.y > mp.y) || (a.y == mp.y && b.y == mp.y)) {
                double x;
                if (a.y == b.y) x = std::min(a.x, b.x);
                else x = a.x + (mp.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if (x >= mp.x && x < best_x) {
                    best_x = x;
                    // Of the edge's endpoints, the one with the larger x is the visibility candidate.
                    hit = (a.x > b.x) ? n : nx;
                    if (a.y == mp.y && a.x == x) hit = n;
                    if (b.y == mp.y && b.x == x) hit = nx;
                    found = true;
                }
            }
            n = nx;
        } while (n != outer_start);
        require(found, "loops", "a hole is not inside the outer loop");

        // A reflex outer vertex inside the triangle (M, I, P) would hide P; the one making the smallest
        // angle with the ray is then visible instead (Eberly §3).
        const Point2 intersection{best_x, mp.y};
        std::size_t visible = hit;
        const Point2 p = pt(hit);
        double best_angle = std::numeric_limits<double>::infinity(), best_distance = best_angle;
        n = outer_start;
        do {
            if (n != hit && !same_point(pt(n), p)) {
                const Point2 r = pt(n);
                const bool reflex = cross(pt(nodes_[n].prev), r, pt(nodes_[n].next)) <= 0;
                if (reflex && inside_or_on(mp, intersection, p, r)) {
                    const double dx = r.x - mp.x, dy = r.y - mp.y;
                    const double angle = std::atan2(std::abs(dy), dx);
                    const double dist = dx * dx + dy * dy;
                    if (angle < best_angle || (angle == best_angle && dist < best_distance)) {
                        best_angle = angle, best_distance = dist, visible = n;
                    }
                }
            }
            n = nodes_[n].next;
        } while (n != outer_start);

        // Splice: ... P, M, (hole in its order) ..., M', P', next(P) ...
        const std::size_t m_copy = nodes_.size();
        nodes_.push_back(Node{nodes_[m].vertex, 0, 0, true});
        const std::size_t p_copy = nodes_.size();
        nodes_.push_back(Node{nodes_[visible].vertex, 0, 0, true});
        const std::size_t p_next = nodes_[visible].next;
        const std::size_t m_prev = nodes_[m].prev;
        link(visible, m);
        link(m_prev, m_copy);
        link(m_copy, p_copy);
        link(p_copy, p_next);
    }

    std::vector<std::array<std::size_t, 3>> clip(std::size_t start) {
        std::vector<std::array<std::size_t, 3>> triangles;
        std::size_t count = 0;
        double remaining_area = 0;
        std::size_t n = start;
        do {
            ++count;
            remaining_area += cross({0, 0}, pt(n), pt(nodes_[n].next));
            n = nodes_[n].next;
        } while (n != start);
        if (count < 3) return triangles;
        triangles.reserve(count - 2);
        quality_.assign(nodes_.size(), 0.0);
        dirty_.assign(nodes_.size(), true);

        std::size_t current = start;
        while (count > 3) {
            std::size_t best = current;
            double best_quality = -std::numeric_limits<double>::infinity();
            bool any_ear = false;
            std::size_t k = current;
            for (std::size_t i = 0; i < count; ++i, k = nodes_[k].next) {
                if (dirty_[k]) quality_[k] = ear_quality(k), dirty_[k] = false;
                double q = quality_[k];
                if (q < 0) continue;
                // Cutting this ear must not leave a remainder of zero area with vertices still to place:
                // those would only fit into degenerate triangles (a fan from the far corner is right).
                const double ear_area = cross(pt(nodes_[k].prev), pt(k), pt(nodes_[k].next));
                if (count > 4 && remaining_area - ear_area <= collinear_) q -= 2.0;
                if (q > best_quality) best_quality = q, best = k, any_ear = true;
            }
            if (!any_ear) {
                // Numerically the polygon has no clean ear left (self-touching input): cut the most convex
                // corner so the loop still terminates with every boundary edge used once.
                best_quality = -std::numeric_limits<double>::infinity();
                k = current;
                for (std::size_t i = 0; i < count; ++i, k = nodes_[k].next) {
                    const double c = cross(pt(nodes_[k].prev), pt(k), pt(nodes_[k].next));
                    if (c > best_quality) best_quality = c, best = k;
                }
            }
            const std::size_t a = nodes_[best].prev, c = nodes_[best].next;
            triangles.push_back({nodes_[a].vertex, nodes_[best].vertex, nodes_[c].vertex});
            remaining_area -= cross(pt(a), pt(best), pt(c));
            nodes_[best].active = false;
            link(a, c);
            dirty_[a] = dirty_[c] = true;
            --count;
            current = a;
        }
        triangles.push_back({nodes_[nodes_[current].prev].vertex, nodes_[current].vertex,
                             nodes_[nodes_[current].next].vertex});
        return triangles;
    }

private:
    const Point2& pt(std::size_t node) const { return points_[nodes_[node].vertex]; }
    void link(std::size_t a, std::size_t b) { nodes_[a].next = b, nodes_[b].prev = a; }

    bool inside_or_on(const Point2& a, const Point2& b, const Point2& c, const Point2& p) const {
        const double orientation = cross(a, b, c) >= 0 ? 1.0 : -1.0;
        return orientation * cross(a, b, p) >= -collinear_ && orientation * cross(b, c, p) >= -collinear_ &&
               orientation * cross(c, a, p) >= -collinear_;
    }

    // The shape quality 4 sqrt(3) A / (a^2 + b^2 + c^2) in (0, 1] of the ear at `node`, or -1 when the
    // corner is not strictly convex or another vertex lies in (or on) the ear.
    double ear_quality(std::size_t node) const {
        const std::size_t ia = nodes_[node].prev, ic = nodes_[node].next;
        const Point2 &a = pt(ia), &b = pt(node), &c = pt(ic);
        const double twice_area = cross(a, b, c);
        if (twice_area <= collinear_) return -1;
        for (std::size_t k = nodes_[ic].next; k != ia; k = nodes_[k].next) {
            const Point2& p = pt(k);
            if (same_point(p, a) || same_point(p, b) || same_point(p, c)) continue;  // a bridge's duplicate
            if (inside_or_on(a, b, c, p)) return -1;
        }
        const double sum = squared_length(a, b) + squared_length(b, c) + squared_length(c, a);
        return 2.0 * std::sqrt(3.0) * twice_area / sum;
    }

    std::vector<Point2> points_;
    std::vector<Node> nodes_;
    std::vector<double> quality_;
    std::vector<bool> dirty_;
    double collinear_ = 0;
};

}  // namespace

double twice_signed_area(const std::vector<Point2>& polygon) {
    double sum = 0;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Point2& a = polygon[k];
        const Point2& b = polygon[(k + 1) % polygon.size()];
        sum += a.x * b.y - a.y * b.x;
    }
    return sum;
}

std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<std::vector<Point2>>& loops) {
    require(!loops.empty(), "loops", "needs an outer loop");
    std::vector<Point2> points;
    std::vector<std::vector<std::size_t>> loop_vertices;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        require(loops[l].size() >= 3, "loops",
                [&] { return "loop " + std::to_string(l) + " has fewer than three vertices"; });
        std::vector<std::size_t> indices(loops[l].size());
        for (std::size_t k = 0; k < loops[l].size(); ++k) {
            require(std::isfinite(loops[l][k].x) && std::isfinite(loops[l][k].y), "loops",
                    [&] { return "loop " + std::to_string(l) + " has a non-finite point"; });
            indices[k] = points.size();
            points.push_back(loops[l][k]);
        }
        // Outer counterclockwise, holes clockwise: the orientation the bridging and clipping assume.
        const bool counterclockwise = twice_signed_area(loops[l]) > 0;
        if (counterclockwise != (l == 0)) std::reverse(indices.begin(), indices.end());
        loop_vertices.push_back(std::move(indices));
    }

    EarClipper clipper(points);
    const std::size_t outer = clipper.add_loop(loop_vertices[0]);
    // Holes are bridged rightmost first so that every later bridge sees the earlier ones as outer edges.
    std::vector<std::size_t> hole_order(loops.size() - 1);
    std::iota(hole_order.begin(), hole_order.end(), std::size_t{1});
    auto max_x = [&](std::size_t l) {
        double m = -std::numeric_limits<double>::infinity();
        for (const Point2& p : loops[l]) m = std::max(m, p.x);
        return m;
    };
    std::sort(hole_order.begin(), hole_order.end(), [&](std::size_t a, std::size_t b) { return max_x(a) > max_x(b); });
    for (std::size_t l : hole_order) clipper.bridge_hole(outer, clipper.add_loop(loop_vertices[l]));
    return clipper.clip(outer);
}

}  // namespace ratbez::detail
