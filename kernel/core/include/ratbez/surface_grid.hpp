#pragma once
// Batched evaluation of a NURBS surface on a tensor grid of parameters us x vs: the points, the points
// and first partials, the points and unit normals, or the points and all partials up to order two, into
// flat structure-of-arrays output.
//
// Evaluating point by point (A4.3) repeats the same work at every point: two span searches (A2.1), two
// basis evaluations (A2.2) and a (p+1) x (q+1) contraction of the control net. On a grid the u basis is
// the same along a whole row and the v basis along a whole column, so evaluate_grid computes each once
// per parameter, contracts the net in u once per row (the row's isocurve in v, Q_c = sum_k N_k(u) P^w_kc),
// and is left with a (q+1)-term dot product per point, which runs vectorised across the points of a
// v span. The result agrees with NurbsSurface::point / derivative / normal to rounding (about 1e-15
// relative); the summation order differs, so not bit for bit.
//
// Instruction sets: the library is built for baseline x86-64 (SSE2), because binaries must run on any
// x86-64 machine. The inner loops are compiled a second time for AVX2 + FMA and chosen once at run time
// when the CPU has both (grid_kernels_name() says which); select_grid_kernels pins the portable ones so
// tests can check both.

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "ratbez/bspline_basis.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

// What evaluate_grid computes at every grid point.
enum class GridOutput {
    points,    // S(u, v)
    partials,  // S, S_u and S_v
    normals,   // S and the unit normal, as NurbsSurface::normal (the limit direction at poles and apexes)
    second_partials,  // S, S_u, S_v, S_uu, S_uv and S_vv (curvature, Newton steps)
};

// One 3D vector per grid point, as three contiguous coordinate arrays (structure of arrays: what the
// vectorised loops write, and what numpy or a GPU upload wants). Grid point (i, j), parameters
// (us[i], vs[j]), is entry i * v_count + j: row-major with v running fastest.
struct GridVectors {
    std::vector<double> x, y, z;

    std::size_t size() const { return x.size(); }
    Vec3 operator[](std::size_t k) const { return {x[k], y[k], z[k]}; }
};

struct SurfaceGrid {
    std::size_t u_count = 0, v_count = 0;
    GridOutput output = GridOutput::points;
    GridVectors points;   // always
    GridVectors du, dv;   // GridOutput::partials and second_partials, else empty
    GridVectors duu, duv, dvv;  // GridOutput::second_partials, else empty
    GridVectors normals;  // GridOutput::normals, else empty

    std::size_t index(std::size_t i, std::size_t j) const { return i * v_count + j; }
    Vec3 point(std::size_t i, std::size_t j) const { return points[index(i, j)]; }
    Vec3 partial_u(std::size_t i, std::size_t j) const { return du[index(i, j)]; }
    Vec3 partial_v(std::size_t i, std::size_t j) const { return dv[index(i, j)]; }
    Vec3 partial_uu(std::size_t i, std::size_t j) const { return duu[index(i, j)]; }
    Vec3 partial_uv(std::size_t i, std::size_t j) const { return duv[index(i, j)]; }
    Vec3 partial_vv(std::size_t i, std::size_t j) const { return dvv[index(i, j)]; }
    Vec3 normal(std::size_t i, std::size_t j) const { return normals[index(i, j)]; }
};

// Evaluates the surface at every (us[i], vs[j]). us and vs: finite, non-decreasing (repeats allowed),
// inside the surface's domain; either may be empty (an empty grid). Throws ratbez::Error naming "us" or
// "vs" otherwise.
SurfaceGrid evaluate_grid(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                          GridOutput output = GridOutput::points);
// The same into `result`, reusing its storage: repeated evaluation of grids of one size allocates nothing
// for the output.
void evaluate_grid(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                   GridOutput output, SurfaceGrid& result);
// The same grid a block of rows at a time, for a caller that wants it in another layout: `block` holds rows
// [first_row, first_row + block.u_count) of the grid (block_rows of them, fewer in the last block) when
// `consume` is called, and is overwritten by the next block. The bases are computed once for the whole
// grid, so blocks small enough to stay in cache (a few thousand points) cost nothing extra. An empty grid
// gives one empty block.
void evaluate_grid_blocks(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                          GridOutput output, std::size_t block_rows, SurfaceGrid& block,
                          const std::function<void(std::size_t first_row, const SurfaceGrid& block)>& consume);
// A uniform u_count x v_count grid over the whole domain, ends included (uniform_parameters); counts >= 2.
SurfaceGrid evaluate_grid(const NurbsSurface& surface, std::size_t u_count, std::size_t v_count,
                          GridOutput output = GridOutput::points);

// `count` >= 2 evenly spaced parameters from domain.min to domain.max, both ends exactly, non-decreasing.
std::vector<double> uniform_parameters(const Interval& domain, std::size_t count);

// Which compiled version of the inner loops evaluate_grid uses.
enum class GridKernels {
    best,      // AVX2 + FMA when the CPU has them, else portable (the default)
    portable,  // the baseline x86-64 (SSE2) build, on every machine
};
void select_grid_kernels(GridKernels kernels);
// "avx2+fma" or "portable": what evaluate_grid runs now.
const char* grid_kernels_name();

}  // namespace ratbez
