// Tensor-product Bézier surfaces, polynomial and rational (000 §1.5, Eq. 1.23, Eq. 1.27–1.28; 002 §25).
// As for curves, everything runs on the homogeneous net P^w_{i,j} (S^w is a polynomial tensor-product
// surface, Eq. 1.27) and projects with H at the end (Eq. 1.28).

#include "ratbez/bezier_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

#include "geometry/limit_normal.hpp"
#include "math/numeric_internal.hpp"
#include "math/rational_derivatives.hpp"
#include "math/weights_internal.hpp"
#include "ratbez/bernstein.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {

namespace {

using detail::to_size;

// A1.5 / Eq. 1.19 on `count` homogeneous points starting at `first`, `stride` apart; the scratch copy keeps
// the net intact.
Vec4 de_casteljau_strided(const Vec4* first, std::size_t count, std::size_t stride, double t) {
    std::vector<Vec4> q(count);
    for (std::size_t i = 0; i < count; ++i) q[i] = first[i * stride];
    for (std::size_t k = 1; k < count; ++k)
        for (std::size_t i = 0; i + k < count; ++i) q[i] = lerp(q[i], q[i + 1], t);
    return q.front();
}

Vec4 de_casteljau(const std::vector<Vec4>& points, double t) {
    return de_casteljau_strided(points.data(), points.size(), 1, t);
}

// `where()` names the control point; it (and the message) is built only on failure: from_homogeneous
// runs for every patch a tessellation or evaluator extracts.
template <class Where>
void validate_weight(double weight, const std::string& argument, Where&& where) {
    require(std::isfinite(weight), argument, [&] { return "weight " + where() + " is not a finite number"; });
    require(weight > 0.0, argument, [&] { return "weight " + where() + " is " + exact_number(weight) + " but must be > 0"; });
}

// "[i][j]", built by appending (GCC 12 reports a false -Wrestrict for "[" + std::to_string(i) at -O3).
std::string index_pair(std::size_t i, std::size_t j) {
    std::string text(1, '[');
    text += std::to_string(i);
    text += "][";
    text += std::to_string(j);
    text += ']';
    return text;
}

// Checks that `net` is a non-empty rectangle of finite points; returns its columns.
std::size_t validate_net(const std::vector<std::vector<Vec3>>& net) {
    require(!net.empty(), "net", "a Bézier surface needs at least one row of control points");
    limits::require_bezier_count(net.size(), "net", "rows");
    const std::size_t columns = net.front().size();
    require(columns > 0, "net", "row 0 is empty; every row needs at least one control point");
    limits::require_bezier_count(columns, "net", "columns");
    for (std::size_t i = 0; i < net.size(); ++i) {
        require(net[i].size() == columns, "net", [&] {
            return "row " + std::to_string(i) + " has " + std::to_string(net[i].size()) + " points but row 0 has " +
                   std::to_string(columns) + " (the net must be rectangular, not ragged)";
        });
        for (std::size_t j = 0; j < columns; ++j)
            require(is_finite(net[i][j]), "net", [&] { return "control point " + index_pair(i, j) + " has a non-finite coordinate"; });
    }
    return columns;
}

}  // namespace

BezierSurface::BezierSurface(int rows, int columns, std::vector<Vec4> homogeneous_points, bool rational,
                             int weight_exponent)
    : ControlNet(rows, columns, std::move(homogeneous_points), rational, weight_exponent) {}

BezierSurface::BezierSurface(std::vector<std::vector<Vec3>> net) {
    const std::size_t columns = validate_net(net);
    rows_ = static_cast<int>(net.size());
    columns_ = static_cast<int>(columns);
    pw_.resize(net.size() * columns);
    for (std::size_t i = 0; i < net.size(); ++i)
        for (std::size_t j = 0; j < columns; ++j) pw_[i * columns + j] = homogenize(net[i][j], 1.0);
    rational_ = false;
}

BezierSurface::BezierSurface(std::vector<std::vector<Vec3>> net, std::vector<std::vector<double>> weights) {
    const std::size_t columns = validate_net(net);
    require(weights.size() == net.size(), "weights", [&] {
        return "has " + std::to_string(weights.size()) + " rows but the net has " + std::to_string(net.size()) +
               "; there must be exactly one weight per control point";
    });
    for (std::size_t i = 0; i < weights.size(); ++i) {
        require(weights[i].size() == columns, "weights", [&] {
            return "row " + std::to_string(i) + " has " + std::to_string(weights[i].size()) +
                   " weights but the net has " + std::to_string(columns) + " columns";
        });
        for (std::size_t j = 0; j < columns; ++j) validate_weight(weights[i][j], "weights", [&] { return index_pair(i, j); });
    }
    std::vector<double> all_weights;
    std::vector<Vec3> all_points;
    for (const auto& row : weights) all_weights.insert(all_weights.end(), row.begin(), row.end());
    for (const auto& row : net) all_points.insert(all_points.end(), row.begin(), row.end());
    weight_exponent_ = detail::weight_scale_exponent_of(all_weights, detail::products_finite(all_points, all_weights));
    rows_ = static_cast<int>(net.size());
    columns_ = static_cast<int>(columns);
    pw_.resize(net.size() * columns);
    for (std::size_t i = 0; i < net.size(); ++i)
        for (std::size_t j = 0; j < columns; ++j)
            pw_[i * columns + j] = homogenize(net[i][j], std::ldexp(weights[i][j], weight_exponent_));
    rational_ = true;
}

BezierSurface BezierSurface::from_homogeneous(int rows, int columns, std::vector<Vec4> homogeneous_points,
                                              bool rational) {
    require(rows >= 1, "rows", [&] { return "must be >= 1, got " + std::to_string(rows); });
    require(columns >= 1, "columns", [&] { return "must be >= 1, got " + std::to_string(columns); });
    limits::require_bezier_count(to_size(rows), "rows", "rows");
    limits::require_bezier_count(to_size(columns), "columns", "columns");
    require(homogeneous_points.size() == to_size(rows) * to_size(columns), "homogeneous_points", [&] {
        return "has " + std::to_string(homogeneous_points.size()) +
               " points but rows x columns = " + std::to_string(to_size(rows) * to_size(columns));
    });
    for (std::size_t i = 0; i < to_size(rows); ++i)
        for (std::size_t j = 0; j < to_size(columns); ++j) {
            const Vec4& p = homogeneous_points[i * to_size(columns) + j];
            require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "homogeneous_points",
                    [&] { return "control point " + index_pair(i, j) + " has a non-finite coordinate"; });
            validate_weight(p.w, "homogeneous_points", [&] { return index_pair(i, j); });
        }
    std::vector<double> weights(homogeneous_points.size());
    for (std::size_t k = 0; k < weights.size(); ++k) weights[k] = homogeneous_points[k].w;
    const int exponent = detail::weight_scale_exponent_of(weights);
    detail::scale_homogeneous(homogeneous_points, exponent);
    return BezierSurface(rows, columns, std::move(homogeneous_points), rational, exponent);
}

Vec3 BezierSurface::point(double u, double v) const { return point_basis(u, v); }

Vec3 BezierSurface::point_basis(double u, double v) const {
    // The row-then-column scheme of A1.6 with Bernstein bases (A1.3) in place of Horner: each row i collapses
    // to b_i = sum_j B_{j,m}(v) P^w_{i,j}, then S^w = sum_i B_{i,n}(u) b_i (Eq. 1.27).
    require_in_domain(u, 0.0, 1.0, "u");
    require_in_domain(v, 0.0, 1.0, "v");  // all_bernstein would report a bad v as "u"
    const std::vector<double> basis_u = all_bernstein(degree_u(), u);
    const std::vector<double> basis_v = all_bernstein(degree_v(), v);
    Vec4 sum;
    for (std::size_t i = 0; i < to_size(rows_); ++i) {
        Vec4 row_sum;
        for (std::size_t j = 0; j < to_size(columns_); ++j) row_sum += basis_v[j] * pw_[i * to_size(columns_) + j];
        sum += basis_u[i] * row_sum;
    }
    return detail::require_finite_point(project(sum), u, v);
}

Vec3 BezierSurface::point_u_first(double u, double v) const {
    // A1.7, first branch: Q_j(u) = deCasteljau in u on column j are the control points of C_u(v) (Eq. 1.24).
    require_in_domain(u, 0.0, 1.0, "u");
    require_in_domain(v, 0.0, 1.0, "v");  // here, not inside the isocurve, which would call it "u"
    return detail::require_finite_point(isocurve_u(u).point_de_casteljau(v), u, v);
}

Vec3 BezierSurface::point_v_first(double u, double v) const {
    // A1.7, second branch: Q_i(v) = deCasteljau in v on row i are the control points of C_v(u).
    require_in_domain(u, 0.0, 1.0, "u");
    require_in_domain(v, 0.0, 1.0, "v");
    return detail::require_finite_point(isocurve_v(v).point_de_casteljau(u), u, v);
}

Vec3 BezierSurface::point_one_step(double u, double v) const {
    require_in_domain(u, 0.0, 1.0, "u");
    require_in_domain(v, 0.0, 1.0, "v");
    // 002 §25.4: p^{k+1}_{i,j} = (1-u)(1-v) p^k_{i,j} + (1-u)v p^k_{i,j+1} + u(1-v) p^k_{i+1,j} + uv p^k_{i+1,j+1}.
    // Each bilinear step lowers both degrees by one; when n != m the min(n, m) bilinear steps leave a single
    // row or column, which ordinary deCasteljau (A1.5) finishes in the remaining direction.
    std::size_t rows = to_size(rows_), columns = to_size(columns_);
    const std::size_t stride = columns;
    std::vector<Vec4> q = pw_;
    const double a = 1.0 - u, b = 1.0 - v;
    while (rows > 1 && columns > 1) {
        for (std::size_t i = 0; i + 1 < rows; ++i)
            for (std::size_t j = 0; j + 1 < columns; ++j)
                q[i * stride + j] = (a * b) * q[i * stride + j] + (a * v) * q[i * stride + j + 1] +
                                    (u * b) * q[(i + 1) * stride + j] + (u * v) * q[(i + 1) * stride + j + 1];
        --rows;
        --columns;
    }
    const Vec4 last = rows > 1 ? de_casteljau_strided(q.data(), rows, stride, u) : de_casteljau_strided(q.data(), columns, 1, v);
    return detail::require_finite_point(project(last), u, v);
}

BezierCurve BezierSurface::isocurve_u(double u0) const {
    require_in_domain(u0, 0.0, 1.0, "u");
    // Eq. 1.24: Q_j(u0) = sum_i B_{i,n}(u0) P^w_{i,j}, computed by deCasteljau down each column j.
    std::vector<Vec4> q(to_size(columns_));
    for (std::size_t j = 0; j < q.size(); ++j) q[j] = de_casteljau_strided(&pw_[j], to_size(rows_), to_size(columns_), u0);
    return BezierCurve::from_homogeneous(std::move(q), rational_);
}

BezierCurve BezierSurface::isocurve_v(double v0) const {
    require_in_domain(v0, 0.0, 1.0, "v");
    // Q_i(v0) = sum_j B_{j,m}(v0) P^w_{i,j}, deCasteljau along each row i.
    std::vector<Vec4> q(to_size(rows_));
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = de_casteljau_strided(&pw_[i * to_size(columns_)], to_size(columns_), 1, v0);
    return BezierCurve::from_homogeneous(std::move(q), rational_);
}

std::vector<std::vector<Vec3>> BezierSurface::derivatives(double u, double v, int order) const {
    require_in_domain(u, 0.0, 1.0, "u");
    require_in_domain(v, 0.0, 1.0, "v");
    limits::require_derivative_order(order, "order");
    const std::size_t d = to_size(order);

    // Homogeneous partials Aw[k][l] = d^{k+l} S^w / du^k dv^l. S^w is a polynomial tensor product, so the
    // curve rule Eq. 1.9 applies in each direction: difference the net k times along u (factor n!/(n-k)!),
    // collapse the columns by deCasteljau in u, difference those points l times along v (m!/(m-l)!), and
    // evaluate by deCasteljau in v. Partials beyond the degree vanish. Flat: aw[k * stride + l].
    const std::size_t stride = d + 1;
    std::vector<Vec4> aw(stride * stride);
    const std::size_t columns = to_size(columns_);
    std::vector<Vec4> net = pw_;
    std::size_t rows = to_size(rows_);
    double factor_u = 1.0;
    for (std::size_t k = 0; k <= d && rows > 0; ++k) {
        std::vector<Vec4> column_points(columns);
        for (std::size_t j = 0; j < columns; ++j)
            column_points[j] = de_casteljau_strided(&net[j], rows, columns, u);
        double factor_v = 1.0;
        for (std::size_t l = 0; k + l <= d && !column_points.empty(); ++l) {
            aw[k * stride + l] = (factor_u * factor_v) * de_casteljau(column_points, v);
            factor_v *= static_cast<double>(column_points.size() - 1);
            for (std::size_t j = 0; j + 1 < column_points.size(); ++j)
                column_points[j] = column_points[j + 1] - column_points[j];
            column_points.pop_back();
        }
        factor_u *= static_cast<double>(rows - 1);
        for (std::size_t i = 0; i + 1 < rows; ++i)
            for (std::size_t j = 0; j < columns; ++j)
                net[i * columns + j] = net[(i + 1) * columns + j] - net[i * columns + j];
        --rows;
    }

    // The quotient rule on A = w S, solved for S (A4.4, rational_derivatives.hpp).
    std::vector<Vec3> flat(stride * stride);
    detail::rational_surface_derivatives(aw, flat, stride);
    detail::require_finite_partials(flat, stride, u, v);
    std::vector<std::vector<Vec3>> skl(d + 1);
    for (std::size_t k = 0; k <= d; ++k) skl[k].assign(flat.begin() + static_cast<std::ptrdiff_t>(k * stride),
                                                       flat.begin() + static_cast<std::ptrdiff_t>(k * stride + d - k + 1));
    return skl;
}

Vec3 BezierSurface::derivative(double u, double v, int du, int dv) const {
    limits::require_partial_orders(du, dv);
    return derivatives(u, v, du + dv)[to_size(du)][to_size(dv)];
}

Vec3 BezierSurface::normal(double u, double v) const {
    // Eq. 1.4 where S_u x S_v does not vanish; where it does (a collapsed edge: S_u = 0 along v = v0, the
    // apex of a cone, a pole) the limit of N along a path into the patch (limit_normal.hpp). Its first term
    // N_0 = S_u x S_v is Eq. 1.4 itself, so the regular case needs no separate test.
    constexpr std::size_t stride = detail::limit_normal_stride;
    Vec3 low = project(pw_.front()), high = low;
    for (const Vec4& p : pw_) {
        const Vec3 q = project(p);
        low = {std::min(low.x, q.x), std::min(low.y, q.y), std::min(low.z, q.z)};
        high = {std::max(high.x, q.x), std::max(high.y, q.y), std::max(high.z, q.z)};
    }
    // A net farther from the origin than 1e3 times its size: the partials of the net relative to its first
    // point (one rounding per coordinate, fused multiply-add), the same partials with the rounding of the
    // net's size rather than of its distance from the origin, which far from it (a unit patch at 1e8) would
    // pass rounding off as a direction at a pole (issue 29). Nearer, the plain partials (normals() agrees).
    // And scaled by a power of two (exactly) to the net's size, so that cross products of the partials of a
    // patch of size 1e-85 do not underflow (nor of 1e80 overflow); the normal does not change with the scale.
    const Vec3 anchor = project(pw_.front());
    const double size = norm(high - low);
    const bool far = norm(anchor) > 1e3 * size;
    const int exponent = size > 0 && std::isfinite(size) ? -std::ilogb(size) : 0;
    std::vector<Vec4> local(pw_.size());
    for (std::size_t k = 0; k < pw_.size(); ++k) {
        const Vec4& p = pw_[k];
        const Vec4 moved = far ? Vec4{std::fma(-p.w, anchor.x, p.x), std::fma(-p.w, anchor.y, p.y),
                                      std::fma(-p.w, anchor.z, p.z), p.w}
                               : p;
        local[k] = {std::ldexp(moved.x, exponent), std::ldexp(moved.y, exponent), std::ldexp(moved.z, exponent), p.w};
    }
    const BezierSurface shifted(rows_, columns_, std::move(local), rational_, weight_exponent_);
    const auto derivatives_uv = shifted.derivatives(u, v, static_cast<int>(stride) - 1);  // validates u and v
    detail::LimitNormalPartials skl;
    for (std::size_t k = 0; k < stride; ++k)
        for (std::size_t l = 0; k + l < stride; ++l) skl[k * stride + l] = derivatives_uv[k][l];

    // Path direction: towards the centre of the domain, so the path stays inside [0,1]^2 from any edge or corner.
    double a = 0.5 - u, b = 0.5 - v;
    const double length = std::sqrt(a * a + b * b);
    if (length > 0.0) {
        a /= length;
        b /= length;
    } else {
        a = 1.0;
        b = 0.0;
    }

    // "Vanishes" is measured against the control net's size, for derivatives of every order: rounding noise in
    // an exactly vanishing partial is never mistaken for a direction. (a, b) is a unit vector: path scale 1.
    std::array<double, stride> floors{};
    std::fill(floors.begin() + 1, floors.end(), std::ldexp(size, exponent));
    if (const auto n = detail::limit_normal(skl, a, b, floors, 1.0)) return *n;
    detail::throw_no_tangent_plane(exact_number(u), exact_number(v));
}

}  // namespace ratbez
