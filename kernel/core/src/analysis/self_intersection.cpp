// The certified self-intersection test of surface strips; see self_intersection.hpp.
#include "analysis/self_intersection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "geometry/surface_evaluator.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/box.hpp"
#include "ratbez/error.hpp"
#include "ratbez/bspline_basis.hpp"

namespace ratbez::detail {

namespace {

// A rectangle of the strip's parameter grid: cell (i, j), the Bézier patch of the i-th u span (counted over
// all pieces) and the j-th v span, is [i, i + 1] x [j, j + 1].
struct Rect {
    double x0, x1, y0, y1;
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
};

struct Node {
    Rect r;
    Box box;
};

// One Bézier patch: its homogeneous net (row-major, i along u), degrees, the box of its control points,
// and where it lies in its piece.
struct Cell {
    std::vector<Vec4> net;
    int p = 0, q = 0;
    Box box;
    std::size_t piece = 0;
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    bool sliver = false;  // smaller than the resolution (a knot span of negligible width): nothing to certify
};

// De Casteljau on one line of homogeneous points (A1.5 at one parameter): the part over [a, b] of [0, 1].
void restrict_line(std::vector<Vec4>& line, double a, double b) {
    const std::size_t n = line.size() - 1;
    if (a > 0) {
        // The right part at a: after level r, line[k] = b_k^r for k <= n - r, so line[k] ends as b_k^{n-k}.
        for (std::size_t level = 1; level <= n; ++level)
            for (std::size_t k = 0; k + level <= n; ++k) line[k] = (1 - a) * line[k] + a * line[k + 1];
        b = (b - a) / (1 - a);
    }
    if (b < 1) {
        // The left part at b: after level r, line[k] = b_{k-r}^r for k >= r, so line[k] ends as b_0^k.
        for (std::size_t level = 1; level <= n; ++level)
            for (std::size_t k = n; k >= level; --k) line[k] = (1 - b) * line[k - 1] + b * line[k];
    }
}

// The net of a patch over [a0, a1] x [b0, b1] of its [0, 1]^2.
std::vector<Vec4> restrict_net(const Cell& cell, double a0, double a1, double b0, double b1) {
    std::vector<Vec4> net = cell.net;
    const std::size_t rows = to_size(cell.p + 1), columns = to_size(cell.q + 1);
    std::vector<Vec4> line;
    if (a0 > 0 || a1 < 1)
        for (std::size_t j = 0; j < columns; ++j) {
            line.clear();
            for (std::size_t i = 0; i < rows; ++i) line.push_back(net[i * columns + j]);
            restrict_line(line, a0, a1);
            for (std::size_t i = 0; i < rows; ++i) net[i * columns + j] = line[i];
        }
    if (b0 > 0 || b1 < 1)
        for (std::size_t i = 0; i < rows; ++i) {
            line.assign(net.begin() + static_cast<std::ptrdiff_t>(i * columns),
                        net.begin() + static_cast<std::ptrdiff_t>((i + 1) * columns));
            restrict_line(line, b0, b1);
            std::copy(line.begin(), line.end(), net.begin() + static_cast<std::ptrdiff_t>(i * columns));
        }
    return net;
}

Box net_box(const std::vector<Vec4>& net) {
    Box box;
    for (const Vec4& q : net) box.add(project(q));
    return box;
}

// Bernstein product (degrees (m1, n1) times (m2, n2)): c_rs = sum_{i+k=r, j+l=s}
// C(m1,i) C(m2,k) / C(m1+m2,r) * C(n1,j) C(n2,l) / C(n1+n2,s) * a_ij b_kl.
std::vector<double> bernstein_product(const std::vector<double>& a, int m1, int n1, const std::vector<double>& b, int m2,
                                      int n2) {
    const int m = m1 + m2, n = n1 + n2;
    std::vector<double> c(to_size((m + 1) * (n + 1)), 0.0);
    for (int i = 0; i <= m1; ++i)
        for (int j = 0; j <= n1; ++j) {
            const double aij = a[to_size(i * (n1 + 1) + j)] * binomial(m1, i) * binomial(n1, j);
            if (aij == 0) continue;
            for (int k = 0; k <= m2; ++k)
                for (int l = 0; l <= n2; ++l)
                    c[to_size((i + k) * (n + 1) + j + l)] += aij * b[to_size(k * (n2 + 1) + l)] * binomial(m2, k) * binomial(n2, l);
        }
    for (int r = 0; r <= m; ++r)
        for (int s = 0; s <= n; ++s) c[to_size(r * (n + 1) + s)] /= binomial(m, r) * binomial(n, s);
    return c;
}

// The Bernstein coefficients of d . (w A_u - w_u A) over the net (the numerator of d . S_u; along v by
// transposing first).
std::vector<double> slope_numerator(const std::vector<Vec4>& net, int p, int q, const Vec3& d) {
    const std::size_t columns = to_size(q + 1);
    std::vector<double> h(net.size()), w(net.size());
    for (std::size_t k = 0; k < net.size(); ++k) {
        h[k] = d.x * net[k].x + d.y * net[k].y + d.z * net[k].z;
        w[k] = net[k].w;
    }
    std::vector<double> hu(to_size(p) * columns), wu(to_size(p) * columns);
    for (int i = 0; i < p; ++i)
        for (std::size_t j = 0; j < columns; ++j) {
            hu[to_size(i) * columns + j] = p * (h[to_size(i + 1) * columns + j] - h[to_size(i) * columns + j]);
            wu[to_size(i) * columns + j] = p * (w[to_size(i + 1) * columns + j] - w[to_size(i) * columns + j]);
        }
    std::vector<double> c = bernstein_product(w, p, q, hu, p - 1, q);
    const std::vector<double> c2 = bernstein_product(wu, p - 1, q, h, p, q);
    for (std::size_t k = 0; k < c.size(); ++k) c[k] -= c2[k];
    return c;
}

std::vector<Vec4> transposed(const std::vector<Vec4>& net, int p, int q) {
    std::vector<Vec4> t(net.size());
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) t[to_size(j * (p + 1) + i)] = net[to_size(i * (q + 1) + j)];
    return t;
}

// Every coefficient strictly of the given sign (beyond rounding of the largest).
bool all_of_sign(const std::vector<double>& c, double sign) {
    double largest = 0;
    for (const double x : c) largest = std::max(largest, std::abs(x));
    const double margin = 1e-12 * largest;
    for (const double x : c)
        if (!(sign * x > margin)) return false;
    return largest > 0;
}

// The axis of a narrow cone containing unit directions g_k: start from their mean and step towards the
// direction of least dot product (Badoiu–Clarkson's iteration for the smallest enclosing ball, on the sphere).
// False when even the best axis found leaves one at a right angle or more (no such cone).
bool cone_axis(const std::vector<Vec3>& directions, Vec3& axis) {
    Vec3 d{};
    for (const Vec3& g : directions) d += g;
    if (!(norm(d) > 0)) return false;
    d = d / norm(d);
    for (int step = 1; step <= 40; ++step) {
        const Vec3* worst = &directions.front();
        for (const Vec3& g : directions)
            if (dot(g, d) < dot(*worst, d)) worst = &g;
        const Vec3 moved = d + *worst * (1.0 / (step + 1));
        if (!(norm(moved) > 0)) break;
        d = moved / norm(moved);
    }
    double least = 1;
    for (const Vec3& g : directions) least = std::min(least, dot(g, d));
    axis = d;
    return least > 0;
}

class Search {
public:
    Search(const SurfaceStrip& strip, double resolution, std::size_t budget)
        : strip_(strip), resolution_(resolution), budget_(budget) {
        for (std::size_t k = 0; k < strip.pieces.size(); ++k) {
            const NurbsSurface& s = strip.pieces[k];
            const std::vector<double> bu = breakpoints(s.degree_u(), s.knots_u()), bv = breakpoints(s.degree_v(), s.knots_v());
            const std::vector<std::vector<BezierSurface>> patches = s.bezier_patches();
            if (k == 0) nv_ = static_cast<int>(patches.front().size());
            require(static_cast<int>(patches.front().size()) == nv_, "surfaces", "the strip's pieces differ in their v spans");
            for (std::size_t a = 0; a < patches.size(); ++a) {
                for (std::size_t b = 0; b < patches[a].size(); ++b) {
                    const BezierSurface& patch = patches[a][b];
                    Cell cell{patch.homogeneous_points(), patch.degree_u(), patch.degree_v(), {}, k, bu[a], bu[a + 1], bv[b], bv[b + 1]};
                    cell.box = net_box(cell.net);
                    size_box_.add(cell.box);
                    cells_.push_back(std::move(cell));
                }
                ++nu_;
            }
        }
        found_distance_ = 1e-10 * size_box_.diagonal();
        for (Cell& c : cells_) c.sliver = c.box.diagonal() <= resolution_;
    }

    SelfIntersection run() {
        const Node root = node({0, static_cast<double>(nu_), 0, static_cast<double>(nv_)});
        self(root);
        return result_;
    }

private:
    const Cell& cell(int i, int j) const {
        i = ((i % nu_) + nu_) % nu_;
        j = ((j % nv_) + nv_) % nv_;
        return cells_[to_size(i * nv_ + j)];
    }

    // The restricted nets of the cells a rectangle covers (its coordinates taken modulo the grid where the
    // strip is closed), with their degrees.
    template <class Visit>
    void for_each_part(const Rect& r, const Visit& visit) const {
        for (int i = static_cast<int>(std::floor(r.x0)); i < static_cast<int>(std::ceil(r.x1)); ++i)
            for (int j = static_cast<int>(std::floor(r.y0)); j < static_cast<int>(std::ceil(r.y1)); ++j) {
                const Cell& c = cell(i, j);
                const double a0 = std::max(r.x0 - i, 0.0), a1 = std::min(r.x1 - i, 1.0);
                const double b0 = std::max(r.y0 - j, 0.0), b1 = std::min(r.y1 - j, 1.0);
                if (!(a1 > a0) || !(b1 > b0)) continue;
                if (c.sliver) continue;  // within the resolution of its neighbours, which are certified
                const bool whole = a0 == 0 && a1 == 1 && b0 == 0 && b1 == 1;
                visit(whole ? c.net : restrict_net(c, a0, a1, b0, b1), c);
            }
    }

    Node node(const Rect& r) const {
        Node n{r, {}};
        const bool whole_cells = r.x0 == std::floor(r.x0) && r.x1 == std::floor(r.x1) && r.y0 == std::floor(r.y0) &&
                                 r.y1 == std::floor(r.y1);
        if (whole_cells) {
            for (int i = static_cast<int>(r.x0); i < static_cast<int>(r.x1); ++i)
                for (int j = static_cast<int>(r.y0); j < static_cast<int>(r.y1); ++j) n.box.add(cell(i, j).box);
        } else {
            for_each_part(r, [&](const std::vector<Vec4>& net, const Cell&) { n.box.add(net_box(net)); });
        }
        return n;
    }

    // The certificate of self_intersection.hpp on a rectangle.
    bool certified(const Rect& r) const {
        struct Part {
            std::vector<Vec4> net;
            int p, q;
        };
        std::vector<Part> parts;
        std::vector<Vec3> along_u, along_v;  // unit tangents at the parts' corners (exact for a Bézier patch)
        for_each_part(r, [&](const std::vector<Vec4>& net, const Cell& c) {
            const std::size_t columns = to_size(c.q + 1), last = to_size(c.p) * columns;
            auto add = [](std::vector<Vec3>& list, const Vec3& d) {
                if (norm(d) > 0) list.push_back(d / norm(d));
            };
            for (const std::size_t j : {std::size_t{0}, columns - 1}) {
                add(along_u, project(net[columns + j]) - project(net[j]));
                add(along_u, project(net[last + j]) - project(net[last - columns + j]));
            }
            for (const std::size_t i : {std::size_t{0}, last}) {
                add(along_v, project(net[i + 1]) - project(net[i]));
                add(along_v, project(net[i + columns - 1]) - project(net[i + columns - 2]));
            }
            parts.push_back({net, c.p, c.q});
        });
        if (parts.empty() || along_u.empty() || along_v.empty()) return false;
        // d+ must make positive dot products with every u and v tangent, d- with every u tangent and every
        // reversed v tangent: each is taken as the axis of the narrowest cone around those directions
        // (the minimax direction, by a few steps towards the worst one), which leaves the most margin.
        std::vector<Vec3> cone_plus = along_u, cone_minus = along_u;
        for (const Vec3& v : along_v) {
            cone_plus.push_back(v);
            cone_minus.push_back(-v);
        }
        Vec3 plus{}, minus{};
        if (!cone_axis(cone_plus, plus) || !cone_axis(cone_minus, minus)) return false;
        for (const Part& part : parts) {
            const std::vector<Vec4> t = transposed(part.net, part.p, part.q);
            if (!all_of_sign(slope_numerator(part.net, part.p, part.q, plus), 1) ||
                !all_of_sign(slope_numerator(part.net, part.p, part.q, minus), 1) ||
                !all_of_sign(slope_numerator(t, part.q, part.p, plus), 1) ||
                !all_of_sign(slope_numerator(t, part.q, part.p, minus), -1))
                return false;
        }
        return true;
    }

    // The two halves of a rectangle: whole cells along the longer run of cells, else halves of the cell along
    // the direction in which its net is longer.
    std::pair<Node, Node> halves(const Node& n) const {
        Rect a = n.r, b = n.r;
        const double cells_x = std::floor(n.r.x1) - std::ceil(n.r.x0), cells_y = std::floor(n.r.y1) - std::ceil(n.r.y0);
        if (n.r.width() > 1 || n.r.height() > 1) {
            if (cells_x >= cells_y && n.r.width() > 1) {
                a.x1 = b.x0 = std::floor(0.5 * (n.r.x0 + n.r.x1));
                if (a.x1 <= n.r.x0) a.x1 = b.x0 = 0.5 * (n.r.x0 + n.r.x1);
            } else {
                a.y1 = b.y0 = std::floor(0.5 * (n.r.y0 + n.r.y1));
                if (a.y1 <= n.r.y0) a.y1 = b.y0 = 0.5 * (n.r.y0 + n.r.y1);
            }
        } else {
            double along_u = 0, along_v = 0;
            for_each_part(n.r, [&](const std::vector<Vec4>& net, const Cell& c) {
                const std::size_t columns = to_size(c.q + 1);
                for (int i = 0; i <= c.p; ++i)
                    for (int j = 0; j <= c.q; ++j) {
                        const Vec3 x = project(net[to_size(i) * columns + to_size(j)]);
                        if (i < c.p) along_u += distance(x, project(net[to_size(i + 1) * columns + to_size(j)]));
                        if (j < c.q) along_v += distance(x, project(net[to_size(i) * columns + to_size(j + 1)]));
                    }
            });
            if (along_u >= along_v) a.x1 = b.x0 = 0.5 * (n.r.x0 + n.r.x1);
            else a.y1 = b.y0 = 0.5 * (n.r.y0 + n.r.y1);
        }
        return {node(a), node(b)};
    }

    // Whether two intervals of a periodic (or not) coordinate touch, and the shift of the second that makes
    // them touch in the unwrapped coordinate.
    static bool touch(double a0, double a1, double b0, double b1, bool periodic, double period, double& shift) {
        for (const double s : {0.0, period, -period}) {
            if (s != 0 && !periodic) continue;
            if (b0 + s <= a1 && a0 <= b1 + s) {
                shift = s;
                return true;
            }
        }
        return false;
    }

    // The rectangle spanning a and b, b shifted by a period where the strip is closed and that brings it
    // nearer; `near` when that rectangle is at most twice as wide and high as a and b together, or within the
    // size of one cell (where a certificate costs no more than on a node).
    std::pair<Rect, bool> span(const Node& a, const Node& b) const {
        auto nearest = [](double a0, double a1, double b0, double b1, bool periodic, double period) {
            double best = 0, gap = std::max(b0 - a1, a0 - b1);
            if (periodic)
                for (const double s : {period, -period}) {
                    const double g = std::max(b0 + s - a1, a0 - b1 - s);
                    if (g < gap) {
                        gap = g;
                        best = s;
                    }
                }
            return best;
        };
        const double sx = nearest(a.r.x0, a.r.x1, b.r.x0, b.r.x1, strip_.closed_u, nu_);
        const double sy = nearest(a.r.y0, a.r.y1, b.r.y0, b.r.y1, strip_.closed_v, nv_);
        const Rect hull{std::min(a.r.x0, b.r.x0 + sx), std::max(a.r.x1, b.r.x1 + sx), std::min(a.r.y0, b.r.y0 + sy),
                        std::max(a.r.y1, b.r.y1 + sy)};
        const bool near = (hull.width() <= 2 * (a.r.width() + b.r.width()) && hull.height() <= 2 * (a.r.height() + b.r.height())) ||
                          (hull.width() <= 1 && hull.height() <= 1);
        return {hull, near};
    }

    bool spent() {
        if (result_.found) return true;
        if (++used_ > budget_) {
            result_.found = result_.undecided = true;
            return true;
        }
        return false;
    }

    void report(const Node& a, const Node* b, bool fold) {
        result_.found = true;
        result_.fold = fold;
        result_.point = a.box.center();
        place(0.5 * (a.r.x0 + a.r.x1), 0.5 * (a.r.y0 + a.r.y1), result_.piece, result_.u, result_.v);
        result_.other_piece = result_.piece;
        result_.other_u = result_.u;
        result_.other_v = result_.v;
        if (b) {
            place(0.5 * (b->r.x0 + b->r.x1), 0.5 * (b->r.y0 + b->r.y1), result_.other_piece, result_.other_u, result_.other_v);
            result_.gap = distance(a.box.center(), b->box.center());
        }
    }

    // Grid coordinates to a piece and its parameters.
    void place(double x, double y, std::size_t& piece, double& u, double& v) const {
        const int i = std::clamp(static_cast<int>(std::floor(x)), 0, nu_ - 1), j = std::clamp(static_cast<int>(std::floor(y)), 0, nv_ - 1);
        const Cell& c = cell(i, j);
        piece = c.piece;
        u = c.u0 + (x - i) * (c.u1 - c.u0);
        v = c.v0 + (y - j) * (c.v1 - c.v0);
    }

    // S and its partials in grid coordinates.
    std::array<Vec3, 3> evaluate(double x, double y) const {
        const int i = std::clamp(static_cast<int>(std::floor(x)), 0, nu_ - 1), j = std::clamp(static_cast<int>(std::floor(y)), 0, nv_ - 1);
        const Cell& c = cell(i, j);
        // The cell's own Bézier patch in its local parameters (x - i, y - j): the partials the search steps in,
        // with no allocation (NurbsSurface::derivatives returns nested vectors; this is the search's inner loop).
        const SurfaceFirstDerivatives d =
            bezier_patch_first_derivatives(c.net.data(), c.p, c.q, std::clamp(x - i, 0.0, 1.0), std::clamp(y - j, 0.0, 1.0));
        return {d.s, d.su, d.sv};
    }

    // Gauss–Newton on S(p) - S(q) = 0 with p in a, q in b (the least-norm step of the 3 x 4 system).
    bool crossing(const Node& a, const Node& b) {
        double px = 0.5 * (a.r.x0 + a.r.x1), py = 0.5 * (a.r.y0 + a.r.y1);
        double qx = 0.5 * (b.r.x0 + b.r.x1), qy = 0.5 * (b.r.y0 + b.r.y1);
        for (int iteration = 0; iteration < 30; ++iteration) {
            const auto sp = evaluate(px, py), sq = evaluate(qx, qy);
            const Vec3 r = sp[0] - sq[0];
            if (norm(r) <= found_distance_) {
                result_.found = true;
                result_.point = 0.5 * (sp[0] + sq[0]);
                place(px, py, result_.piece, result_.u, result_.v);
                place(qx, qy, result_.other_piece, result_.other_u, result_.other_v);
                result_.gap = norm(r);
                return true;
            }
            const std::array<Vec3, 4> j{sp[1], sp[2], -sq[1], -sq[2]};
            // (J J^T) y = r, step = -J^T y.
            double m[3][3] = {};
            for (const Vec3& c : j) {
                const double cv[3] = {c.x, c.y, c.z};
                for (int k = 0; k < 3; ++k)
                    for (int l = 0; l < 3; ++l) m[k][l] += cv[k] * cv[l];
            }
            const double trace = m[0][0] + m[1][1] + m[2][2];
            for (int k = 0; k < 3; ++k) m[k][k] += 1e-14 * trace;
            const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
            if (!(std::abs(det) > 0)) return false;
            const double rv[3] = {r.x, r.y, r.z};
            double y[3];
            for (int k = 0; k < 3; ++k) {
                double mk[3][3];
                for (int a_ = 0; a_ < 3; ++a_)
                    for (int b_ = 0; b_ < 3; ++b_) mk[a_][b_] = b_ == k ? rv[a_] : m[a_][b_];
                y[k] = (mk[0][0] * (mk[1][1] * mk[2][2] - mk[1][2] * mk[2][1]) - mk[0][1] * (mk[1][0] * mk[2][2] - mk[1][2] * mk[2][0]) +
                        mk[0][2] * (mk[1][0] * mk[2][1] - mk[1][1] * mk[2][0])) / det;
            }
            const Vec3 yv{y[0], y[1], y[2]};
            px = std::clamp(px - dot(j[0], yv), a.r.x0, a.r.x1);
            py = std::clamp(py - dot(j[1], yv), a.r.y0, a.r.y1);
            qx = std::clamp(qx - dot(j[2], yv), b.r.x0, b.r.x1);
            qy = std::clamp(qy - dot(j[3], yv), b.r.y0, b.r.y1);
        }
        return false;
    }

    // Gauss–Newton on N = S_u x S_v = 0 inside a rectangle (N's partials from the second derivatives): a point
    // without a tangent plane, where the surface pinches or folds (a Whitney umbrella's pinch point starts a
    // curve along which the surface meets itself). Found when |N| <= 1e-10 max(|S_u|, |S_v|)^2 (one partial
    // vanishing, as at a pinch, counts too).
    bool singular_point(const Node& n) {
        double x = 0.5 * (n.r.x0 + n.r.x1), y = 0.5 * (n.r.y0 + n.r.y1);
        for (int iteration = 0; iteration < 25; ++iteration) {
            const int i = std::clamp(static_cast<int>(std::floor(x)), 0, nu_ - 1), j = std::clamp(static_cast<int>(std::floor(y)), 0, nv_ - 1);
            const Cell& c = cell(i, j);
            const double du = c.u1 - c.u0, dv = c.v1 - c.v0;
            const auto d = strip_.pieces[c.piece].derivatives(std::clamp(c.u0 + (x - i) * du, c.u0, c.u1),
                                                              std::clamp(c.v0 + (y - j) * dv, c.v0, c.v1), 2);
            const Vec3 su = d[1][0] * du, sv = d[0][1] * dv, suu = d[2][0] * (du * du), suv = d[1][1] * (du * dv), svv = d[0][2] * (dv * dv);
            const Vec3 normal = cross(su, sv);
            // Relative to the larger partial: a pinch, where one partial vanishes, counts as well as a fold.
            const double scale = std::max(dot(su, su), dot(sv, sv));
            if (!(scale > 0)) return false;
            if (norm(normal) <= 1e-10 * scale) {
                result_.found = result_.fold = true;
                result_.point = d[0][0];
                place(x, y, result_.piece, result_.u, result_.v);
                result_.other_piece = result_.piece;
                result_.other_u = result_.u;
                result_.other_v = result_.v;
                return true;
            }
            const Vec3 nx = cross(suu, sv) + cross(su, suv), ny = cross(suv, sv) + cross(su, svv);
            const double a = dot(nx, nx), b = dot(nx, ny), e = dot(ny, ny), det = a * e - b * b;
            if (!(det > 1e-30 * (a * e))) return false;
            const double gx = dot(nx, normal), gy = dot(ny, normal);
            x = std::clamp(x - (e * gx - b * gy) / det, n.r.x0, n.r.x1);
            y = std::clamp(y - (a * gy - b * gx) / det, n.r.y0, n.r.y1);
        }
        return false;
    }

    static bool overlap(const Box& a, const Box& b) {
        return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z &&
               b.min.z <= a.max.z;
    }

    // Whether a rectangle lies within one sliver cell.
    bool in_sliver(const Rect& r) const {
        const int i = static_cast<int>(std::floor(r.x0)), j = static_cast<int>(std::floor(r.y0));
        return r.x1 <= i + 1 && r.y1 <= j + 1 && cell(i, j).sliver;
    }

    void self(const Node& n) {
        if (spent() || in_sliver(n.r) || certified(n.r)) return;
        if (n.r.width() <= 1 && n.r.height() <= 1 && singular_point(n)) return;
        if (n.box.diagonal() < resolution_) return report(n, nullptr, true);
        const auto [a, b] = halves(n);
        self(a);
        self(b);
        pair(a, b);
    }

    void pair(const Node& a, const Node& b) {
        if (spent() || !overlap(a.box, b.box)) return;
        double sx = 0, sy = 0;
        const bool adjacent = touch(a.r.x0, a.r.x1, b.r.x0, b.r.x1, strip_.closed_u, nu_, sx) &&
                              touch(a.r.y0, a.r.y1, b.r.y0, b.r.y1, strip_.closed_v, nv_, sy);
        if (adjacent && (in_sliver(a.r) || in_sliver(b.r))) return;  // a sliver only touches its neighbours
        // The rectangle spanning both (across a seam where that is nearer): one-to-one there means a and b
        // do not meet. Tried for touching pairs and for near ones (the span at most about twice their sizes).
        const auto [hull, near] = span(a, b);
        if ((adjacent || near) && (hull.width() < nu_ || !strip_.closed_u) && (hull.height() < nv_ || !strip_.closed_v) &&
            certified(hull))
            return;
        if (!adjacent && a.r.width() <= 1 && a.r.height() <= 1 && b.r.width() <= 1 && b.r.height() <= 1 && crossing(a, b))
            return;
        if (a.box.diagonal() < resolution_ && b.box.diagonal() < resolution_) return report(a, &b, adjacent);
        const bool split_a = a.box.diagonal() >= b.box.diagonal();
        const auto [c1, c2] = halves(split_a ? a : b);
        pair(c1, split_a ? b : a);
        pair(c2, split_a ? b : a);
    }

    const SurfaceStrip& strip_;
    double resolution_;
    std::size_t budget_, used_ = 0;
    std::vector<Cell> cells_;
    int nu_ = 0, nv_ = 0;
    Box size_box_;
    double found_distance_ = 0;
    SelfIntersection result_;
};

}  // namespace

SelfIntersection find_self_intersection(const SurfaceStrip& strip, double resolution, std::size_t budget) {
    return Search(strip, resolution, budget).run();
}

}  // namespace ratbez::detail
