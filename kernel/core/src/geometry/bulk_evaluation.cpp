// Evaluation at many parameters at once (bulk_evaluation.hpp).

#include "ratbez/bulk_evaluation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/surface_grid.hpp"

namespace ratbez {
namespace {

using detail::exact_number;

void require_parameter(double t, const Interval& domain, std::string_view argument, std::size_t index) {
    if (!std::isfinite(t)) fail(argument, "element " + std::to_string(index) + " is not a finite number");
    if (t < domain.min || t > domain.max)
        fail(argument, "element " + std::to_string(index) + " (" + exact_number(t) + ") is outside the domain [" +
                           exact_number(domain.min) + ", " + exact_number(domain.max) + "]");
}

void require_parameters(std::span<const double> ts, const Interval& domain, std::string_view argument) {
    for (std::size_t k = 0; k < ts.size(); ++k) require_parameter(ts[k], domain, argument, k);
}

void require_order(int order, std::string_view argument) {
    require(order >= 0, argument, [&] { return "the derivative order must be >= 0, got " + std::to_string(order); });
}

void require_output(std::span<double> out, std::size_t points) {
    require(out.size() == 3 * points, "out", [&] {
        return "needs room for " + std::to_string(points) + " points (" + std::to_string(3 * points) +
               " numbers), got " + std::to_string(out.size());
    });
}

void store(std::span<double> out, std::size_t k, const Vec3& p) {
    out[3 * k] = p.x, out[3 * k + 1] = p.y, out[3 * k + 2] = p.z;
}

template <class Curve>
void evaluate_curve_points(const Curve& curve, std::span<const double> us, int order, const Interval& domain,
                           std::span<double> out) {
    require_order(order, "order");
    require_parameters(us, domain, "us");
    require_output(out, us.size());
    for (std::size_t k = 0; k < us.size(); ++k)
        store(out, k, order == 0 ? curve.point(us[k]) : curve.derivative(us[k], order));
}

// Parameters in ascending order and where each came from: sorted[r] = ts[from[r]]. `from` stays empty
// when ts is already non-decreasing (the common case: linspace), so nothing is copied or scattered.
struct Ascending {
    std::vector<double> sorted;
    std::vector<std::size_t> from;

    Ascending(std::span<const double> ts) {
        if (std::is_sorted(ts.begin(), ts.end())) return;
        from.resize(ts.size());
        std::iota(from.begin(), from.end(), std::size_t{0});
        std::stable_sort(from.begin(), from.end(), [&](std::size_t a, std::size_t b) { return ts[a] < ts[b]; });
        sorted.resize(ts.size());
        for (std::size_t r = 0; r < ts.size(); ++r) sorted[r] = ts[from[r]];
    }
    std::span<const double> values(std::span<const double> ts) const { return from.empty() ? ts : sorted; }
    std::size_t original(std::size_t r) const { return from.empty() ? r : from[r]; }
};

// The grid output that holds the wanted vectors, and the members of SurfaceGrid they are in, in the order
// they are interleaved at each point.
struct GridChoice {
    GridOutput output;
    std::vector<GridVectors SurfaceGrid::*> vectors;
};

std::optional<GridChoice> grid_choice(int du, int dv, bool normals) {
    if (normals) return GridChoice{GridOutput::normals, {&SurfaceGrid::normals}};
    if (du == 0 && dv == 0) return GridChoice{GridOutput::points, {&SurfaceGrid::points}};
    if (du + dv == 1) return GridChoice{GridOutput::partials, {du == 1 ? &SurfaceGrid::du : &SurfaceGrid::dv}};
    if (du + dv == 2)
        return GridChoice{GridOutput::second_partials,
                          {du == 2 ? &SurfaceGrid::duu : du == 1 ? &SurfaceGrid::duv : &SurfaceGrid::dvv}};
    return std::nullopt;  // third and higher partials: point by point
}

// Writes the block's rows [0, grid.u_count) of the M chosen vectors into `out`, interleaved: the M vectors
// of a point one after the other. M is a template parameter so that the copy loop unrolls (the D0 grid
// runs at the speed of memory).
template <std::size_t M>
void interleave_block(const SurfaceGrid& grid, const std::vector<GridVectors SurfaceGrid::*>& members,
                      std::size_t first, const Ascending& u_order, const Ascending& v_order, std::size_t nv,
                      std::span<double> out) {
    std::array<const GridVectors*, M> vectors{};
    for (std::size_t k = 0; k < M; ++k) vectors[k] = &(grid.*members[k]);
    const auto copy = [&](std::size_t at, double* p) {
        for (std::size_t k = 0; k < M; ++k, p += 3)
            p[0] = vectors[k]->x[at], p[1] = vectors[k]->y[at], p[2] = vectors[k]->z[at];
    };
    for (std::size_t r = 0; r < grid.u_count; ++r) {
        double* row = out.data() + 3 * M * u_order.original(first + r) * nv;
        if (v_order.from.empty()) {
            for (std::size_t j = 0; j < nv; ++j) copy(r * nv + j, row + 3 * M * j);
        } else {
            for (std::size_t j = 0; j < nv; ++j) copy(r * nv + j, row + 3 * M * v_order.from[j]);
        }
    }
}

// The grid a block of rows at a time (evaluate_grid_blocks: each block's coordinate arrays are still in
// cache when read back), interleaved into `out`, scattered back to the caller's order when the parameters
// came unsorted.
void interleave_grid(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                     const GridChoice& choice, std::span<double> out) {
    const Ascending u_order(us), v_order(vs);
    const std::size_t nv = vs.size();
    constexpr std::size_t block_points = 4096;
    const std::size_t block_rows = std::max<std::size_t>(1, block_points / std::max<std::size_t>(nv, 1));
    SurfaceGrid block;
    evaluate_grid_blocks(surface, u_order.values(us), v_order.values(vs), choice.output, block_rows, block,
                         [&](std::size_t first, const SurfaceGrid& grid) {
        switch (choice.vectors.size()) {
            case 1: return interleave_block<1>(grid, choice.vectors, first, u_order, v_order, nv, out);
            case 3: return interleave_block<3>(grid, choice.vectors, first, u_order, v_order, nv, out);
            default: return interleave_block<6>(grid, choice.vectors, first, u_order, v_order, nv, out);
        }
    });
}

// The checks every grid call makes: parameters inside the domain, a grid whose size fits, and room for
// `per_point` vectors at each grid point.
void require_grid(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                  std::size_t per_point, std::span<double> out) {
    require_parameters(us, surface.domain_u(), "us");
    require_parameters(vs, surface.domain_v(), "vs");
    require(vs.empty() || us.size() <= std::numeric_limits<std::size_t>::max() / 3 / per_point / vs.size(), "us",
            "the grid is too large");
    require_output(out, us.size() * vs.size() * per_point);
}

void evaluate_grid_checked(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                           int du, int dv, bool normals, std::span<double> out) {
    require_order(du, "du");
    require_order(dv, "dv");
    require_grid(surface, us, vs, 1, out);
    if (us.empty() || vs.empty()) return;
    if (const auto choice = grid_choice(du, dv, normals)) {
        interleave_grid(surface, us, vs, *choice, out);
        return;
    }
    for (std::size_t i = 0; i < us.size(); ++i)
        for (std::size_t j = 0; j < vs.size(); ++j)
            store(out, i * vs.size() + j, surface.derivative(us[i], vs[j], du, dv));
}

}  // namespace

void evaluate_curve(const NurbsCurve& curve, std::span<const double> us, int order, std::span<double> out) {
    evaluate_curve_points(curve, us, order, curve.domain(), out);
}

void evaluate_curve(const BezierCurve& curve, std::span<const double> us, int order, std::span<double> out) {
    evaluate_curve_points(curve, us, order, Interval{0.0, 1.0}, out);
}

void evaluate_surface_grid(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                           int du, int dv, std::span<double> out) {
    evaluate_grid_checked(surface, us, vs, du, dv, false, out);
}

void evaluate_surface_partials(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                               int order, std::span<double> out) {
    require(order == 1 || order == 2, "order", [&] { return "must be 1 or 2, got " + std::to_string(order); });
    GridChoice choice{GridOutput::partials, {&SurfaceGrid::points, &SurfaceGrid::du, &SurfaceGrid::dv}};
    if (order == 2) {
        choice.output = GridOutput::second_partials;
        choice.vectors.insert(choice.vectors.end(), {&SurfaceGrid::duu, &SurfaceGrid::duv, &SurfaceGrid::dvv});
    }
    require_grid(surface, us, vs, choice.vectors.size(), out);
    if (us.empty() || vs.empty()) return;
    interleave_grid(surface, us, vs, choice, out);
}

void evaluate_surface_normals(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                              std::span<double> out) {
    evaluate_grid_checked(surface, us, vs, 0, 0, true, out);
}

void evaluate_surface_at(const NurbsSurface& surface, std::span<const double> uv, int du, int dv,
                         std::span<double> out) {
    require_order(du, "du");
    require_order(dv, "dv");
    require(uv.size() % 2 == 0, "uv", "needs (u, v) pairs: an even number of parameters");
    const std::size_t count = uv.size() / 2;
    const Interval domain_u = surface.domain_u(), domain_v = surface.domain_v();
    for (std::size_t k = 0; k < count; ++k) {
        // Named as numpy indexes the (N, 2) array: uv[k, 0] is u, uv[k, 1] is v.
        for (int c = 0; c < 2; ++c) {
            const double t = uv[2 * k + static_cast<std::size_t>(c)];
            const Interval& domain = c == 0 ? domain_u : domain_v;
            if (!std::isfinite(t) || t < domain.min || t > domain.max)
                fail("uv", "row " + std::to_string(k) + ": " + (c == 0 ? "u" : "v") + " = " + exact_number(t) +
                               (std::isfinite(t) ? " is outside the domain [" + exact_number(domain.min) + ", " +
                                                       exact_number(domain.max) + "]"
                                                 : " is not a finite number"));
        }
    }
    require_output(out, count);
    const bool point = du == 0 && dv == 0;
    for (std::size_t k = 0; k < count; ++k) {
        const double u = uv[2 * k], v = uv[2 * k + 1];
        store(out, k, point ? surface.point(u, v) : surface.derivative(u, v, du, dv));
    }
}

}  // namespace ratbez
