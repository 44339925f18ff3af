// Tensor-product NURBS surfaces S(u,v) = H{ sum_i sum_j N_{i,p}(u) N_{j,q}(v) P^w_ij } (001; the standard
// NURBS algorithms cited inline). S^w is a polynomial tensor product in 4D, so every algorithm works on it
// and only the final projection (A4.3) or the quotient rule (A4.4) knows about weights. The directional
// operations (knot insertion A5.3, decomposition A5.7, isocurves) are the curve algorithms applied to the
// columns (u) or rows (v) of the net, exactly as the surface algorithms are defined.

#include "ratbez/nurbs_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "geometry/limit_normal.hpp"
#include "math/numeric_internal.hpp"
#include "math/rational_derivatives.hpp"
#include "math/weights_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {
namespace {

using detail::number;
using detail::to_size;

using detail::Scratch;  // small work arrays on the stack, on the heap when large

void require_weight(double w, const std::string& where, const std::string& argument) {
    require(std::isfinite(w) && w > 0.0, argument,
            [&] { return "weight " + where + " is " + number(w) + "; weights must be finite and > 0"; });
}

std::string index_pair(std::size_t i, std::size_t j) {
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "(" + std::to_string(i).
    std::string text(1, '(');
    text += std::to_string(i);
    text += ", ";
    text += std::to_string(j);
    text += ')';
    return text;
}

// The span of t in its domain (A2.1), validated under the caller's parameter name ("u" or "v").
int span_of(int degree, const std::vector<double>& knots, double t, std::string_view name) {
    const Interval d = knot_domain(degree, knots);
    require_in_domain(t, d.min, d.max, name);
    return find_span(degree, knots, t);
}

// The span to differentiate in when moving from t in direction `direction`: at an interior knot a step to
// the left needs the span on the left (its one-sided derivatives), which A2.1's half-open spans do not give.
int span_towards(int degree, const std::vector<double>& knots, double t, double direction) {
    const int span = find_span(degree, knots, t);
    if (direction < 0.0 && t == knots[to_size(span)] && span > degree)
        return static_cast<int>(std::lower_bound(knots.begin(), knots.end(), t) - knots.begin()) - 1;
    return span;
}

void reset_polynomial_weights(std::vector<Vec4>& pw) {
    for (Vec4& p : pw) p.w = 1.0;
}

}  // namespace

// ---- construction --------------------------------------------------------------------------------------

NurbsSurface::NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                           std::vector<Vec4> homogeneous_points, bool rational, int weight_exponent)
    : ControlNet(static_cast<int>(knots_u.size()) - degree_u - 1, static_cast<int>(knots_v.size()) - degree_v - 1,
                 std::move(homogeneous_points), rational, weight_exponent),
      degree_u_(degree_u),
      degree_v_(degree_v),
      knots_u_(std::move(knots_u)),
      knots_v_(std::move(knots_v)) {}

namespace {

// The checks shared by the two public constructors; `weights` is null for a polynomial surface. Sizes
// first, values after. Returns the row-major homogeneous net, weights scaled by 2^weight_exponent.
std::vector<Vec4> validated_net(int degree_u, int degree_v, const std::vector<double>& knots_u,
                                const std::vector<double>& knots_v, const std::vector<std::vector<Vec3>>& net,
                                const std::vector<std::vector<double>>* weights, int& weight_exponent) {
    limits::require_degree(degree_u, "degree_u");
    limits::require_degree(degree_v, "degree_v");
    require(!net.empty() && !net.front().empty(), "net", "a NURBS surface needs at least one control point");
    const std::size_t rows = net.size(), columns = net.front().size();
    limits::require_surface_points(rows, columns, "net");
    for (std::size_t i = 0; i < rows; ++i) {
        require(net[i].size() == columns, "net", [&] {
            return "row " + std::to_string(i) + " has " + std::to_string(net[i].size()) + " points but row 0 has " +
                   std::to_string(columns) + " (the net must be rectangular)";
        });
        for (std::size_t j = 0; j < columns; ++j)
            require(is_finite(net[i][j]), "net",
                    [&] { return "control point " + index_pair(i, j) + " has a non-finite coordinate"; });
    }
    if (weights != nullptr) {
        require(weights->size() == rows, "weights", [&] {
            return "has " + std::to_string(weights->size()) + " rows for a net of " + std::to_string(rows);
        });
        for (std::size_t i = 0; i < rows; ++i) {
            require((*weights)[i].size() == columns, "weights", [&] {
                return "row " + std::to_string(i) + " has " + std::to_string((*weights)[i].size()) +
                       " entries for a net row of " + std::to_string(columns);
            });
            for (std::size_t j = 0; j < columns; ++j) require_weight((*weights)[i][j], index_pair(i, j), "weights");
        }
    }
    require(rows >= to_size(degree_u) + 1, "net", [&] {
        return "degree " + std::to_string(degree_u) + " in u needs at least " + std::to_string(to_size(degree_u) + 1) +
               " rows, got " + std::to_string(rows);
    });
    require(columns >= to_size(degree_v) + 1, "net", [&] {
        return "degree " + std::to_string(degree_v) + " in v needs at least " + std::to_string(to_size(degree_v) + 1) +
               " columns, got " + std::to_string(columns);
    });
    validate_knot_vector(degree_u, knots_u, static_cast<int>(rows), "knots_u");
    validate_knot_vector(degree_v, knots_v, static_cast<int>(columns), "knots_v");

    weight_exponent = 0;
    if (weights != nullptr) {
        std::vector<double> all;
        std::vector<Vec3> all_points;
        for (const auto& row : *weights) all.insert(all.end(), row.begin(), row.end());
        for (const auto& row : net) all_points.insert(all_points.end(), row.begin(), row.end());
        weight_exponent = detail::weight_scale_exponent_of(all, detail::products_finite(all_points, all));
    }
    std::vector<Vec4> pw(rows * columns);
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < columns; ++j)
            pw[i * columns + j] = homogenize(net[i][j], weights ? std::ldexp((*weights)[i][j], weight_exponent) : 1.0);
    return pw;
}

}  // namespace

NurbsSurface::NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                           std::vector<std::vector<Vec3>> net) {
    int exponent = 0;
    std::vector<Vec4> pw = validated_net(degree_u, degree_v, knots_u, knots_v, net, nullptr, exponent);
    *this = NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(pw), false, exponent);
}

NurbsSurface::NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                           std::vector<std::vector<Vec3>> net, std::vector<std::vector<double>> weights) {
    int exponent = 0;
    std::vector<Vec4> pw = validated_net(degree_u, degree_v, knots_u, knots_v, net, &weights, exponent);
    *this = NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(pw), true, exponent);
}

NurbsSurface NurbsSurface::from_homogeneous(int degree_u, int degree_v, std::vector<double> knots_u,
                                            std::vector<double> knots_v, std::vector<Vec4> homogeneous_points,
                                            bool rational) {
    limits::require_degree(degree_u, "degree_u");
    limits::require_degree(degree_v, "degree_v");
    require(knots_u.size() >= 2 * to_size(degree_u) + 2, "knots_u", [&] {
        return "degree " + std::to_string(degree_u) + " needs at least " + std::to_string(2 * to_size(degree_u) + 2) +
               " knots, got " + std::to_string(knots_u.size());
    });
    require(knots_v.size() >= 2 * to_size(degree_v) + 2, "knots_v", [&] {
        return "degree " + std::to_string(degree_v) + " needs at least " + std::to_string(2 * to_size(degree_v) + 2) +
               " knots, got " + std::to_string(knots_v.size());
    });
    const std::size_t rows = knots_u.size() - to_size(degree_u) - 1;
    const std::size_t columns = knots_v.size() - to_size(degree_v) - 1;
    limits::require_surface_points(rows, columns, "homogeneous_points");
    require(homogeneous_points.size() == rows * columns, "homogeneous_points", [&] {
        return "has " + std::to_string(homogeneous_points.size()) + " points, the knots need " + std::to_string(rows) +
               " x " + std::to_string(columns);
    });
    for (std::size_t k = 0; k < homogeneous_points.size(); ++k) {
        Vec4& p = homogeneous_points[k];
        const std::string where = index_pair(k / columns, k % columns);
        require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "homogeneous_points",
                [&] { return "control point " + where + " has a non-finite coordinate"; });
        require_weight(p.w, where, "homogeneous_points");
        if (!rational) {
            require(std::abs(p.w - 1.0) <= 1e-12, "homogeneous_points", [&] {
                return "weight " + where + " is " + number(p.w) + ", but a non-rational surface has weights 1";
            });
            p = homogenize(project(p), 1.0);
        }
    }
    validate_knot_vector(degree_u, knots_u, static_cast<int>(rows), "knots_u");
    validate_knot_vector(degree_v, knots_v, static_cast<int>(columns), "knots_v");
    std::vector<double> weights(homogeneous_points.size());
    for (std::size_t k = 0; k < weights.size(); ++k) weights[k] = homogeneous_points[k].w;
    const int exponent = detail::weight_scale_exponent_of(weights);
    detail::scale_homogeneous(homogeneous_points, exponent);
    return NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(homogeneous_points),
                        rational, exponent);
}

NurbsSurface NurbsSurface::from_bezier(const BezierSurface& surface) {
    // 001: a Bézier patch is the tensor-product B-spline on {0..0, 1..1} in both directions.
    auto bezier_knots = [](int degree) {
        std::vector<double> knots(2 * to_size(degree + 1), 0.0);
        std::fill(knots.begin() + degree + 1, knots.end(), 1.0);
        return knots;
    };
    return NurbsSurface(surface.degree_u(), surface.degree_v(), bezier_knots(surface.degree_u()),
                        bezier_knots(surface.degree_v()), surface.homogeneous_points(), surface.is_rational(),
                        surface.weight_exponent_);
}

Interval NurbsSurface::domain_u() const { return knot_domain(degree_u_, knots_u_); }
Interval NurbsSurface::domain_v() const { return knot_domain(degree_v_, knots_v_); }

Box NurbsSurface::control_box() const {
    Box box;
    for (const Vec4& p : pw_) box.add(project(p));
    return box;
}

// ---- evaluation ----------------------------------------------------------------------------------------

Vec4 NurbsSurface::homogeneous_point(double u, double v) const {
    // A3.5 on P^w: S^w = sum_l N_{vspan-q+l,q}(v) (sum_k N_{uspan-p+k,p}(u) P^w_{uspan-p+k, vspan-q+l}).
    const int span_u = span_of(degree_u_, knots_u_, u, "u");
    const int span_v = span_of(degree_v_, knots_v_, v, "v");
    Scratch<double, 32> basis_u_buffer(to_size(degree_u_) + 1), basis_v_buffer(to_size(degree_v_) + 1);
    const std::span<double> basis_u = basis_u_buffer.values(), basis_v = basis_v_buffer.values();
    basis_functions(span_u, u, degree_u_, knots_u_, basis_u);
    basis_functions(span_v, v, degree_v_, knots_v_, basis_v);
    Vec4 sum;
    for (std::size_t l = 0; l < basis_v.size(); ++l) {
        Vec4 column_sum;
        const int j = span_v - degree_v_ + static_cast<int>(l);
        for (std::size_t k = 0; k < basis_u.size(); ++k)
            column_sum += basis_u[k] * homogeneous_point(span_u - degree_u_ + static_cast<int>(k), j);
        sum += basis_v[l] * column_sum;
    }
    return sum;
}

Vec3 NurbsSurface::point(double u, double v) const {
    // A4.3: A3.5 in homogeneous space, then H (skipped for a polynomial surface, whose w is 1 up to rounding).
    const Vec4 sw = homogeneous_point(u, v);
    return detail::require_finite_point(rational_ ? project(sw) : weighted_part(sw), u, v);
}

namespace {

// A3.6 on P^w at given spans: aw[k * (order + 1) + l] = d^{k+l} S^w / du^k dv^l for k + l <= order (zero
// above the degrees), then A4.4 for the Euclidean partials skl[k * (order + 1) + l]. Allocation-free for
// low orders and degrees (the normal's regular case).
// `origin`: when given, the control points are taken relative to it (w (P - origin), w, one rounding each
// by a fused multiply-add): the partials of order >= 1 are the same, with the rounding of the points' size
// instead of their distance from the coordinate origin (normal(), far from it).
void surface_partials(const NurbsSurface& s, double u, double v, int span_u, int span_v, int order,
                      std::span<Vec4> aw, std::span<Vec3> skl, const Vec3* origin = nullptr) {
    const auto control = [&](int i, int j) {
        const Vec4& pw = s.homogeneous_point(i, j);
        if (origin == nullptr) return pw;
        return Vec4{std::fma(-pw.w, origin->x, pw.x), std::fma(-pw.w, origin->y, pw.y), std::fma(-pw.w, origin->z, pw.z),
                    pw.w};
    };
    const int p = s.degree_u(), q = s.degree_v();
    const std::size_t stride = to_size(order) + 1;
    const int du = std::min(order, p), dv = std::min(order, q);
    const std::size_t width_u = to_size(p) + 1, width_v = to_size(q) + 1;
    Scratch<double, 96> nu_buffer(to_size(du + 1) * width_u), nv_buffer(to_size(dv + 1) * width_v);
    const std::span<double> nu = nu_buffer.values(), nv = nv_buffer.values();
    basis_function_derivatives(span_u, u, p, s.knots_u(), du, nu);
    basis_function_derivatives(span_v, v, q, s.knots_v(), dv, nv);

    std::fill(aw.begin(), aw.begin() + static_cast<std::ptrdiff_t>(stride * stride), Vec4{});
    Scratch<Vec4, 32> temp_buffer(width_v);
    const std::span<Vec4> temp = temp_buffer.values();
    for (int k = 0; k <= du; ++k) {
        for (std::size_t column = 0; column < width_v; ++column) {
            temp[column] = Vec4{};
            const int j = span_v - q + static_cast<int>(column);
            for (std::size_t r = 0; r < width_u; ++r)
                temp[column] += nu[to_size(k) * width_u + r] * control(span_u - p + static_cast<int>(r), j);
        }
        const int highest_l = std::min(order - k, dv);
        for (int l = 0; l <= highest_l; ++l) {
            Vec4 sum;
            for (std::size_t column = 0; column < width_v; ++column) sum += nv[to_size(l) * width_v + column] * temp[column];
            aw[to_size(k) * stride + to_size(l)] = sum;
        }
    }

    // A4.4 (rational_derivatives.hpp); a polynomial surface has w = 1 identically and no quotient to form.
    if (s.is_rational()) {
        detail::rational_surface_derivatives(aw, skl, stride);
        return;
    }
    for (std::size_t k = 0; k < stride; ++k)
        for (std::size_t l = 0; k + l < stride; ++l) skl[k * stride + l] = weighted_part(aw[k * stride + l]);
}

}  // namespace

std::vector<std::vector<Vec3>> NurbsSurface::derivatives(double u, double v, int order) const {
    limits::require_derivative_order(order, "order");
    const int span_u = span_of(degree_u_, knots_u_, u, "u");
    const int span_v = span_of(degree_v_, knots_v_, v, "v");
    const std::size_t stride = to_size(order) + 1;
    Scratch<Vec4, 16> aw(stride * stride);
    Scratch<Vec3, 16> skl(stride * stride);
    surface_partials(*this, u, v, span_u, span_v, order, aw.values(), skl.values());
    detail::require_finite_partials(skl.values(), stride, u, v);
    std::vector<std::vector<Vec3>> result(stride);
    for (std::size_t k = 0; k < stride; ++k) {
        result[k].resize(stride - k);  // SKL[k][l] for k + l <= order
        for (std::size_t l = 0; k + l < stride; ++l) result[k][l] = skl.values()[k * stride + l];
    }
    return result;
}

Vec3 NurbsSurface::derivative(double u, double v, int du, int dv) const {
    limits::require_partial_orders(du, dv);
    return derivatives(u, v, du + dv)[to_size(du)][to_size(dv)];
}

Vec3 NurbsSurface::normal(double u, double v) const {
    // Eq. 1.4: N = S_u x S_v / |S_u x S_v| wherever that cross product does not vanish.
    const int span_u = span_of(degree_u_, knots_u_, u, "u");
    const int span_v = span_of(degree_v_, knots_v_, v, "v");

    // "Vanishes" is measured against the size of the control points of the current span patch divided by
    // the span lengths: rounding leaves partials of that relative size (about 1e-16) where a collapsed
    // edge makes them exactly zero, and they must not be mistaken for a direction. A patch farther from the
    // origin than kFarFromOrigin times its size has its partials taken relative to its first control point
    // (surface_partials' origin), so that their rounding is of the patch's size wherever it lies: a unit
    // sphere at 1e8 keeps the normal at its poles (measured against the distance from the origin, as
    // before, every partial there looked like rounding: "no tangent plane", issue 29). Nearer, the rounding
    // of the distance is far below the floor, and the partials are the plain ones (normals() agrees).
    const Vec3 anchor = project(homogeneous_point(span_u - degree_u_, span_v - degree_v_));
    double extent = 0.0;
    for (int i = span_u - degree_u_; i <= span_u; ++i)
        for (int j = span_v - degree_v_; j <= span_v; ++j)
            extent = std::max(extent, norm(project(homogeneous_point(i, j)) - anchor));
    constexpr double kFarFromOrigin = 1e3;
    const Vec3* shift = norm(anchor) > kFarFromOrigin * extent ? &anchor : nullptr;
    if (!(extent > 0)) extent = norm(anchor);  // a patch collapsed to one point: no tangent plane anywhere
    else if (!shift) extent += norm(anchor);
    // The partials are scaled by a power of two (exactly) to the patch's size: S_u x S_v of a sphere of
    // radius 1e-85 is 1e-170, whose squared length underflows, and 1e160 for 1e80, whose overflows; the
    // normal and every test below are invariant under the common scale (issue 29: "no tangent plane" below
    // a size of about 1e-85).
    const int scale_exponent = extent > 0 && std::isfinite(extent) ? -std::ilogb(extent) : 0;
    const auto scaled = [scale_exponent](const Vec3& v) {
        return Vec3{std::ldexp(v.x, scale_exponent), std::ldexp(v.y, scale_exponent), std::ldexp(v.z, scale_exponent)};
    };
    extent = std::ldexp(extent, scale_exponent);
    const double length_u = knots_u_[to_size(span_u) + 1] - knots_u_[to_size(span_u)];
    const double length_v = knots_v_[to_size(span_v) + 1] - knots_v_[to_size(span_v)];
    const double span_length = std::min(length_u, length_v);
    constexpr double relative_tolerance = 1e-10;

    {
        std::array<Vec4, 4> aw;
        std::array<Vec3, 4> skl;
        surface_partials(*this, u, v, span_u, span_v, 1, aw, skl, shift);
        const Vec3 su = scaled(skl[2]), sv = scaled(skl[1]);  // stride 2: [k * 2 + l]
        const Vec3 n = cross(su, sv);
        const double length = norm(n);
        const double floor_u = relative_tolerance * extent / length_u;
        const double floor_v = relative_tolerance * extent / length_v;
        if (norm(su) > floor_u && norm(sv) > floor_v && length > relative_tolerance * norm(su) * norm(sv))
            return n / length;
    }

    // A collapsed edge (S_u = 0 along a pole row, S_v = 0 at an apex) or a cusp: the limit of N along a path
    // into the surface (limit_normal.hpp). The path heads for the middle of the domain, so it stays inside
    // from every edge and corner.
    const Interval du = domain_u(), dv = domain_v();
    double a = (du.min + du.max) / 2 - u, b = (dv.min + dv.max) / 2 - v;
    const double path_length = std::hypot(a / (du.max - du.min), b / (dv.max - dv.min));
    if (path_length > 0.0) {
        a /= path_length;
        b /= path_length;
    } else {
        a = du.max - du.min;
        b = 0.0;
    }
    // Derivatives one-sided in the direction of the path (they differ across a knot of reduced continuity).
    const int path_span_u = span_towards(degree_u_, knots_u_, u, a);
    const int path_span_v = span_towards(degree_v_, knots_v_, v, b);

    constexpr std::size_t stride = detail::limit_normal_stride;
    std::array<Vec4, stride * stride> aw;
    detail::LimitNormalPartials skl;
    surface_partials(*this, u, v, path_span_u, path_span_v, static_cast<int>(stride) - 1, aw, skl, shift);
    for (Vec3& partial : skl) partial = scaled(partial);

    // Partials of total order k below extent / span_length^k are rounding noise (see above); the path is
    // not a unit vector, so N_q scales with max(|a|, |b|)^q.
    std::array<double, stride> floors{};
    for (std::size_t k = 1; k < stride; ++k) floors[k] = extent / std::pow(span_length, static_cast<double>(k));
    if (const auto n = detail::limit_normal(skl, a, b, floors, std::max(std::abs(a), std::abs(b)))) return *n;
    detail::throw_no_tangent_plane(number(u), number(v));
}

// ---- isocurves -----------------------------------------------------------------------------------------

NurbsCurve NurbsSurface::isocurve_u(double u0) const { return isocurve(true, u0); }
NurbsCurve NurbsSurface::isocurve_v(double v0) const { return isocurve(false, v0); }

NurbsCurve NurbsSurface::isocurve(bool fixed_u, double t0) const {
    // C_{u0}(v) = H{ sum_j (sum_i N_{i,p}(u0) P^w_ij) N_{j,q}(v) }: every column collapsed by the u basis
    // at u0 into one control point of a curve in v; the same with the roles swapped for C_{v0}(u).
    const int degree = fixed_u ? degree_u_ : degree_v_;
    const int span = span_of(degree, fixed_u ? knots_u_ : knots_v_, t0, fixed_u ? "u" : "v");
    Scratch<double, 32> basis_buffer(to_size(degree) + 1);
    const std::span<double> basis = basis_buffer.values();
    basis_functions(span, t0, degree, fixed_u ? knots_u_ : knots_v_, basis);
    const int count = fixed_u ? columns_ : rows_;
    std::vector<Vec4> q(to_size(count));
    for (int line = 0; line < count; ++line)
        for (std::size_t k = 0; k < basis.size(); ++k) {
            const int across = span - degree + static_cast<int>(k);
            q[to_size(line)] += basis[k] * (fixed_u ? homogeneous_point(across, line) : homogeneous_point(line, across));
        }
    if (!rational_) reset_polynomial_weights(q);
    return fixed_u ? NurbsCurve(degree_v_, knots_v_, std::move(q), rational_, 0)
                   : NurbsCurve(degree_u_, knots_u_, std::move(q), rational_, 0);
}

// ---- knot insertion and decomposition ------------------------------------------------------------------

namespace {

void require_insertable(int degree, const std::vector<double>& knots, double t, int times, const std::string& name) {
    require(times >= 0, "times", [&] { return "must be >= 0, got " + std::to_string(times); });
    const Interval d = knot_domain(degree, knots);
    require_in_domain(t, d.min, d.max, name);
    const int multiplicity = static_cast<int>(std::count(knots.begin(), knots.end(), t));
    // Inserting 0 times is a no-op even at a clamped end, whose multiplicity p + 1 exceeds the degree.
    require(times == 0 || times <= degree - multiplicity, "times", [&] {
        return "inserting " + name + " = " + number(t) + " (" + std::to_string(times) +
               " more times) would raise its multiplicity from " + std::to_string(multiplicity) + " to " +
               std::to_string(static_cast<long long>(multiplicity) + times) + ", more than the degree " + std::to_string(degree);
    });
}

}  // namespace

NurbsSurface NurbsSurface::insert_knot_u(double u, int times) const {
    require_insertable(degree_u_, knots_u_, u, times, "u");
    if (times == 0) return *this;
    // A5.3 in u: A5.1 on every column of the net (the coefficients depend only on the knots).
    std::vector<NurbsCurve> columns;
    columns.reserve(to_size(columns_));
    for (int j = 0; j < columns_; ++j) {
        std::vector<Vec4> column(to_size(rows_));
        for (int i = 0; i < rows_; ++i) column[to_size(i)] = homogeneous_point(i, j);
        columns.push_back(NurbsCurve(degree_u_, knots_u_, std::move(column), rational_, 0).insert_knot(u, times));
    }
    const std::size_t new_rows = columns.front().homogeneous_points().size();
    std::vector<Vec4> pw(new_rows * to_size(columns_));
    for (std::size_t j = 0; j < columns.size(); ++j)
        for (std::size_t i = 0; i < new_rows; ++i) pw[i * columns.size() + j] = columns[j].homogeneous_points()[i];
    return NurbsSurface(degree_u_, degree_v_, columns.front().knots(), knots_v_, std::move(pw), rational_, weight_exponent_);
}

NurbsSurface NurbsSurface::insert_knot_v(double v, int times) const {
    require_insertable(degree_v_, knots_v_, v, times, "v");
    if (times == 0) return *this;
    // A5.3 in v: A5.1 on every row of the net.
    std::vector<Vec4> pw;
    std::vector<double> knots_v;
    for (int i = 0; i < rows_; ++i) {
        std::vector<Vec4> row(pw_.begin() + static_cast<std::ptrdiff_t>(i) * columns_,
                              pw_.begin() + static_cast<std::ptrdiff_t>(i + 1) * columns_);
        const NurbsCurve refined = NurbsCurve(degree_v_, knots_v_, std::move(row), rational_, 0).insert_knot(v, times);
        pw.insert(pw.end(), refined.homogeneous_points().begin(), refined.homogeneous_points().end());
        if (i == 0) knots_v = refined.knots();
    }
    return NurbsSurface(degree_u_, degree_v_, knots_u_, std::move(knots_v), std::move(pw), rational_, weight_exponent_);
}

std::vector<std::vector<BezierSurface>> NurbsSurface::bezier_patches() const {
    // A5.7: A5.6 on every column (u direction) gives strips of p + 1 rows per u span; A5.6 on every row of
    // each strip (v direction) cuts it into patches. Every column shares knots_u, so every column yields
    // the same number of segments in the same order (likewise the rows of a strip).
    std::vector<std::vector<BezierCurve>> column_segments(to_size(columns_));
    for (int j = 0; j < columns_; ++j) {
        std::vector<Vec4> column(to_size(rows_));
        for (int i = 0; i < rows_; ++i) column[to_size(i)] = homogeneous_point(i, j);
        column_segments[to_size(j)] = NurbsCurve(degree_u_, knots_u_, std::move(column), rational_, 0).bezier_segments();
    }
    const std::size_t segments_u = column_segments.front().size();
    const std::size_t patch_rows = to_size(degree_u_) + 1, patch_columns = to_size(degree_v_) + 1;

    std::vector<std::vector<BezierSurface>> patches(segments_u);
    for (std::size_t a = 0; a < segments_u; ++a) {
        // strip_rows[i]: the v-direction segments of row i of the a-th strip.
        std::vector<std::vector<BezierCurve>> strip_rows(patch_rows);
        for (std::size_t i = 0; i < patch_rows; ++i) {
            std::vector<Vec4> row(to_size(columns_));
            for (std::size_t j = 0; j < row.size(); ++j) row[j] = column_segments[j][a].homogeneous_points()[i];
            strip_rows[i] = NurbsCurve(degree_v_, knots_v_, std::move(row), rational_, 0).bezier_segments();
        }
        const std::size_t segments_v = strip_rows.front().size();
        patches[a].reserve(segments_v);
        for (std::size_t b = 0; b < segments_v; ++b) {
            std::vector<Vec4> net(patch_rows * patch_columns);
            for (std::size_t i = 0; i < patch_rows; ++i)
                for (std::size_t j = 0; j < patch_columns; ++j)
                    net[i * patch_columns + j] = strip_rows[i][b].homogeneous_points()[j];
            // The surface's weight scale, as NurbsCurve::bezier_segments keeps the curve's.
            patches[a].push_back(BezierSurface(static_cast<int>(patch_rows), static_cast<int>(patch_columns),
                                               std::move(net), rational_, weight_exponent_));
        }
    }
    return patches;
}

}  // namespace ratbez
