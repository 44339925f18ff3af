// Batched tensor-grid evaluation of NURBS surfaces (see surface_grid.hpp for the idea).
//
// Cost per grid point with u_count x v_count parameters, degrees p (u) and q (v):
//  - basis functions: A2.2 (and the first derivatives, A2.3 for k = 1) once per parameter: O(p^2 + q^2)
//    per row or column, nothing per point;
//  - the u contraction Q_c = sum_k N_{fu+k}(u) P^w_{fu+k, c} once per row, only over the columns the
//    v parameters touch: O((p+1) x columns) per row;
//  - per point, a (q+1)-term dot product of 4-vectors (x3 for the partials) and one reciprocal.
// The per-point loop runs over the points of one v span at a time, where the q+1 coefficients Q_c are
// fixed: it reads q+1 contiguous basis arrays and writes contiguous coordinate arrays, which is exactly
// the shape compilers vectorise (2 points per SSE2 instruction, 4 per AVX2 instruction).
//
// Rational surfaces are evaluated homogeneously and projected once per point, S = A / w; the first
// partials by the quotient rule S_u = (A_u - w_u S) / w (the first-order case of A4.4).

#include "ratbez/surface_grid.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"

// "This loop's iterations are independent" for GCC (ivdep). Clang does not know ivdep, and its nearest
// hint, vectorize(assume_safety), warns wherever it cannot vectorise: clang (the fuzz build) gets none.
#if defined(__clang__)
#define RATBEZ_INDEPENDENT_ITERATIONS
#else
#define RATBEZ_INDEPENDENT_ITERATIONS _Pragma("GCC ivdep")
#endif

namespace ratbez {
namespace {

using detail::exact_number;

std::size_t to_size(int value) { return static_cast<std::size_t>(value); }

void validate_parameters(std::span<const double> ts, const Interval& domain, const char* argument) {
    for (std::size_t k = 0; k < ts.size(); ++k) {
        const double t = ts[k];
        if (!std::isfinite(t))
            throw Error(argument, "element " + std::to_string(k) + " is not a finite number");
        if (t < domain.min || t > domain.max)
            throw Error(argument, "element " + std::to_string(k) + " (" + exact_number(t) +
                        ") is outside the domain [" + exact_number(domain.min) + ", " + exact_number(domain.max) + "]");
        if (k > 0 && t < ts[k - 1])
            throw Error(argument, "must be non-decreasing, but element " + std::to_string(k) +
                        " (" + exact_number(t) + ") is less than element " + std::to_string(k - 1) + " (" +
                        exact_number(ts[k - 1]) + ")");
    }
}

// The non-zero basis functions of one direction at sorted parameters t_0 <= t_1 <= ...
// values[l * count + k] = N_{first[k] + l, p}(t_k), l = 0..p: for a fixed l the values of all parameters
// are contiguous, which is the layout the per-point loops read.
struct DirectionBasis {
    int degree = 0;
    std::size_t count = 0;
    std::vector<int> first;            // span - degree: the first control point index of each parameter
    std::vector<double> values;
    std::vector<double> derivatives;   // same layout, d/dt; empty unless requested
};

// A2.1 (FindSpan) for sorted parameters: the span index only moves forward, so one walk over the knots
// replaces a binary search per parameter. Same convention as find_span: u_k <= t < u_{k+1}, and at the
// domain's end the last non-empty span. A2.2 (BasisFuns) then gives the values; the first derivatives
// come from the same last step of the triangle (A2.3 for k = 1, i.e. Eq. 2.9):
//   N'_{s-p+r,p} = p (N_{s-p+r,p-1} / (u_{s+r} - u_{s+r-p}) - N_{s-p+r+1,p-1} / (u_{s+r+1} - u_{s+r+1-p})),
// and both quotients are the `temp` values A2.2 computes in its last pass anyway. Every denominator
// spans the non-empty span [u_s, u_{s+1}], so none is zero.
void compute_basis(int degree, std::span<const double> knots, int control_count, std::span<const double> ts,
                   bool with_derivatives, DirectionBasis& out) {
    const std::size_t p = to_size(degree);
    const std::size_t n = ts.size();
    out.degree = degree;
    out.count = n;
    out.first.resize(n);
    out.values.resize((p + 1) * n);
    if (with_derivatives) out.derivatives.resize((p + 1) * n);
    else out.derivatives.clear();

    std::vector<double> work(p + 1);  // the triangle of A2.2, one row at a time (once per call)
    const int last_span = control_count - 1;
    int span = degree;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = ts[k];
        while (span < last_span && knots[to_size(span) + 1] <= t) ++span;
        while (knots[to_size(span)] == knots[to_size(span) + 1]) --span;  // t at the domain's end
        out.first[k] = span - degree;

        const std::size_t s = to_size(span);
        work[0] = 1.0;
        for (std::size_t j = 1; j <= p; ++j) {
            const bool last_pass = j == p;
            double saved = 0.0, previous_temp = 0.0;
            for (std::size_t r = 0; r < j; ++r) {
                const double right = knots[s + r + 1] - t;
                const double left = t - knots[s + 1 + r - j];
                const double temp = work[r] / (right + left);
                if (last_pass && with_derivatives)
                    out.derivatives[r * n + k] = static_cast<double>(degree) * (previous_temp - temp);
                previous_temp = temp;
                work[r] = saved + right * temp;
                saved = left * temp;
            }
            work[j] = saved;
            if (last_pass && with_derivatives) out.derivatives[p * n + k] = static_cast<double>(degree) * previous_temp;
        }
        if (p == 0 && with_derivatives) out.derivatives[k] = 0.0;
        for (std::size_t l = 0; l <= p; ++l) out.values[l * n + k] = work[l];
    }
}

// A maximal run of consecutive v parameters in the same knot span: [begin, end) share the q+1
// coefficients Q_{first..first+q}.
struct Run {
    std::size_t begin, end;
    int first;
};

std::vector<Run> span_runs(const DirectionBasis& basis) {
    std::vector<Run> runs;
    for (std::size_t k = 0; k < basis.count;) {
        std::size_t end = k + 1;
        while (end < basis.count && basis.first[end] == basis.first[k]) ++end;
        runs.push_back({k, end, basis.first[k]});
        k = end;
    }
    return runs;
}

// Everything the row loops need, prepared once per call.
struct GridJob {
    const NurbsSurface* surface = nullptr;
    std::span<const double> us, vs;
    GridOutput output = GridOutput::points;
    bool rational = false;
    DirectionBasis u_basis, v_basis;
    std::vector<Run> runs;
    int column_min = 0, column_max = 0;  // the control net columns the v parameters touch
    std::vector<Vec4> q, dq;             // the row's isocurve coefficients and their u derivatives
    std::vector<double> scratch;         // normals: the row's partials (6 x v_count)
    std::size_t row_begin = 0, row_end = 0;  // the rows of the current block; result holds only them
    SurfaceGrid* result = nullptr;
};

// The per-point loops, one run (one v span) at a time. Degree is a template argument so that the
// (q+1)-term sums unroll and the loop over points vectorises; Degree < 0 is the generic fallback for
// degrees above 7 (and 0), which reads the degree at run time. They are always inlined into the
// ISA-specific row functions below, so each of those compiles them for its own instruction set.
template <int Degree, bool Rational>
[[gnu::always_inline]] inline void points_run(const Run& run, int runtime_degree, const double* __restrict nv,
                                              std::size_t stride, const Vec4* __restrict q,
                                              double* __restrict ox, double* __restrict oy, double* __restrict oz) {
    if constexpr (Degree >= 0) {
        // The run's coefficients in locals (registers once unrolled): the stores below cannot alias them.
        double cx[Degree + 1], cy[Degree + 1], cz[Degree + 1], cw[Degree + 1];
        for (int l = 0; l <= Degree; ++l) {
            const Vec4& c = q[run.first + l];
            cx[l] = c.x, cy[l] = c.y, cz[l] = c.z, cw[l] = c.w;
        }
        // The outputs never overlap the inputs (restrict), but after inlining GCC no longer knows that and
        // would need more run-time alias checks than it allows: ivdep states the loop is SIMD-safe.
RATBEZ_INDEPENDENT_ITERATIONS
        for (std::size_t j = run.begin; j < run.end; ++j) {
            double x = 0, y = 0, z = 0, w = 0;
            // Fully unrolled, so that the loop over j is innermost and vectorises across points.
#pragma GCC unroll 8
            for (int l = 0; l <= Degree; ++l) {
                const double b = nv[to_size(l) * stride + j];
                x += b * cx[l], y += b * cy[l], z += b * cz[l];
                if constexpr (Rational) w += b * cw[l];
            }
            if constexpr (Rational) {
                const double r = 1.0 / w;
                x *= r, y *= r, z *= r;
            }
            ox[j] = x, oy[j] = y, oz[j] = z;
        }
    } else {
        for (std::size_t j = run.begin; j < run.end; ++j) {
            Vec4 a{};
            for (int l = 0; l <= runtime_degree; ++l) a += nv[to_size(l) * stride + j] * q[run.first + l];
            if constexpr (Rational) {
                const double r = 1.0 / a.w;
                a.x *= r, a.y *= r, a.z *= r;
            }
            ox[j] = a.x, oy[j] = a.y, oz[j] = a.z;
        }
    }
}

// Points and first partials: A = sum N_l(v) Q_l, A_u = sum N_l(v) dQ_l, A_v = sum N'_l(v) Q_l (homogeneous),
// then S = A / w, S_u = (A_u - w_u S) / w, S_v = (A_v - w_v S) / w.
template <int Degree, bool Rational>
[[gnu::always_inline]] inline void partials_run(const Run& run, int runtime_degree, const double* __restrict nv,
                                                const double* __restrict dnv, std::size_t stride,
                                                const Vec4* __restrict q, const Vec4* __restrict dq,
                                                // Separate restrict parameters, not a struct of pointers:
                                                // GCC keeps the no-alias facts of parameters through
                                                // inlining, and needs them to vectorise nine output streams.
                                                double* __restrict ox, double* __restrict oy, double* __restrict oz,
                                                double* __restrict dux, double* __restrict duy,
                                                double* __restrict duz, double* __restrict dvx,
                                                double* __restrict dvy, double* __restrict dvz) {
    auto finish = [&](std::size_t j, double x, double y, double z, double w, double xu, double yu, double zu,
                      double wu, double xv, double yv, double zv, double wv) {
        if constexpr (Rational) {
            const double r = 1.0 / w;
            x *= r, y *= r, z *= r;
            xu = (xu - wu * x) * r, yu = (yu - wu * y) * r, zu = (zu - wu * z) * r;
            xv = (xv - wv * x) * r, yv = (yv - wv * y) * r, zv = (zv - wv * z) * r;
        }
        ox[j] = x, oy[j] = y, oz[j] = z;
        dux[j] = xu, duy[j] = yu, duz[j] = zu;
        dvx[j] = xv, dvy[j] = yv, dvz[j] = zv;
    };
    if constexpr (Degree >= 0) {
        double cx[Degree + 1], cy[Degree + 1], cz[Degree + 1], cw[Degree + 1];
        double ex[Degree + 1], ey[Degree + 1], ez[Degree + 1], ew[Degree + 1];
        for (int l = 0; l <= Degree; ++l) {
            const Vec4& c = q[run.first + l];
            const Vec4& e = dq[run.first + l];
            cx[l] = c.x, cy[l] = c.y, cz[l] = c.z, cw[l] = c.w;
            ex[l] = e.x, ey[l] = e.y, ez[l] = e.z, ew[l] = e.w;
        }
RATBEZ_INDEPENDENT_ITERATIONS
        for (std::size_t j = run.begin; j < run.end; ++j) {
            double x = 0, y = 0, z = 0, w = 0, xu = 0, yu = 0, zu = 0, wu = 0, xv = 0, yv = 0, zv = 0, wv = 0;
#pragma GCC unroll 8
            for (int l = 0; l <= Degree; ++l) {
                const double b = nv[to_size(l) * stride + j];
                const double db = dnv[to_size(l) * stride + j];
                x += b * cx[l], y += b * cy[l], z += b * cz[l];
                xu += b * ex[l], yu += b * ey[l], zu += b * ez[l];
                xv += db * cx[l], yv += db * cy[l], zv += db * cz[l];
                if constexpr (Rational) w += b * cw[l], wu += b * ew[l], wv += db * cw[l];
            }
            finish(j, x, y, z, w, xu, yu, zu, wu, xv, yv, zv, wv);
        }
    } else {
        for (std::size_t j = run.begin; j < run.end; ++j) {
            Vec4 a{}, au{}, av{};
            for (int l = 0; l <= runtime_degree; ++l) {
                const double b = nv[to_size(l) * stride + j];
                const double db = dnv[to_size(l) * stride + j];
                a += b * q[run.first + l];
                au += b * dq[run.first + l];
                av += db * q[run.first + l];
            }
            finish(j, a.x, a.y, a.z, a.w, au.x, au.y, au.z, au.w, av.x, av.y, av.z, av.w);
        }
    }
}

// Unit normals from the partials. A point whose S_u x S_v is small against |S_u|^2 + |S_v|^2 (a pole, an
// apex, a point on a revolution axis, or within about 1e-6 of one in parameter) gets NaN here and is
// redone by NurbsSurface::normal, which decides with its own, finer criterion (1e-10 of the span patch's
// scale) whether the point is regular or needs the limit direction. The threshold here is deliberately
// coarser, so every point that normal() would treat specially goes to it: the cross product of partials
// that are mostly rounding noise would point anywhere, and the few flagged points cost nothing on a grid.
[[gnu::always_inline]] inline void normals_row(std::size_t count, const double* __restrict ux,
                                               const double* __restrict uy, const double* __restrict uz,
                                               const double* __restrict vx, const double* __restrict vy,
                                               const double* __restrict vz, double* __restrict nx,
                                               double* __restrict ny, double* __restrict nz) {
    constexpr double degenerate = 1e-12;  // (1e-6)^2: the test is on squared lengths
RATBEZ_INDEPENDENT_ITERATIONS
    for (std::size_t j = 0; j < count; ++j) {
        const double cx = uy[j] * vz[j] - uz[j] * vy[j];
        const double cy = uz[j] * vx[j] - ux[j] * vz[j];
        const double cz = ux[j] * vy[j] - uy[j] * vx[j];
        const double length2 = cx * cx + cy * cy + cz * cz;
        const double scale2 = ux[j] * ux[j] + uy[j] * uy[j] + uz[j] * uz[j] + vx[j] * vx[j] + vy[j] * vy[j] +
                              vz[j] * vz[j];
        const double r = length2 > degenerate * scale2 * scale2 ? 1.0 / std::sqrt(length2)
                                                                 : std::numeric_limits<double>::quiet_NaN();
        nx[j] = cx * r, ny[j] = cy * r, nz[j] = cz * r;
    }
}

// Q_c = sum_k N_k(u) P^w_{first+k, c} (and dQ_c with N'_k(u)) for the columns the grid touches: the
// row's isocurve in v. The inner loop over columns is a contiguous axpy on Vec4s.
[[gnu::always_inline]] inline void contract_row(const GridJob& job, std::size_t i, Vec4* __restrict q,
                                                Vec4* __restrict dq) {
    const NurbsSurface& s = *job.surface;
    const std::size_t p = to_size(job.u_basis.degree);
    const std::size_t n = job.u_basis.count;
    const std::size_t columns = to_size(s.columns());
    const std::size_t c0 = to_size(job.column_min), c1 = to_size(job.column_max) + 1;
    const Vec4* __restrict net = s.homogeneous_points().data();
    const std::size_t first = to_size(job.u_basis.first[i]);
    const bool derivatives = dq != nullptr;
    for (std::size_t c = c0; c < c1; ++c) q[c] = Vec4{};
    if (derivatives)
        for (std::size_t c = c0; c < c1; ++c) dq[c] = Vec4{};
    for (std::size_t k = 0; k <= p; ++k) {
        const Vec4* __restrict row = net + (first + k) * columns;
        const double b = job.u_basis.values[k * n + i];
        for (std::size_t c = c0; c < c1; ++c) q[c] += b * row[c];
        if (derivatives) {
            const double db = job.u_basis.derivatives[k * n + i];
            for (std::size_t c = c0; c < c1; ++c) dq[c] += db * row[c];
        }
    }
}

template <int Degree, bool Rational>
[[gnu::always_inline]] inline void evaluate_rows_for(GridJob& job) {
    SurfaceGrid& g = *job.result;
    const std::size_t nv = job.v_basis.count;
    const int degree = job.v_basis.degree;
    const double* nvb = job.v_basis.values.data();
    const double* dnvb = job.v_basis.derivatives.data();
    Vec4* q = job.q.data();
    Vec4* dq = job.output == GridOutput::points ? nullptr : job.dq.data();
    for (std::size_t i = job.row_begin; i < job.row_end; ++i) {
        contract_row(job, i, q, dq);
        const std::size_t offset = (i - job.row_begin) * nv;
        if (job.output == GridOutput::points) {
            for (const Run& run : job.runs)
                points_run<Degree, Rational>(run, degree, nvb, nv, q, g.points.x.data() + offset,
                                             g.points.y.data() + offset, g.points.z.data() + offset);
            continue;
        }
        double* px = g.points.x.data() + offset;
        double* py = g.points.y.data() + offset;
        double* pz = g.points.z.data() + offset;
        if (job.output == GridOutput::partials) {
            const std::size_t o = offset;
            for (const Run& run : job.runs)
                partials_run<Degree, Rational>(run, degree, nvb, dnvb, nv, q, dq, px, py, pz, g.du.x.data() + o,
                                               g.du.y.data() + o, g.du.z.data() + o, g.dv.x.data() + o,
                                               g.dv.y.data() + o, g.dv.z.data() + o);
        } else {
            // Normals: the partials go to the row scratch, then become unit normals.
            double* s = job.scratch.data();
            for (const Run& run : job.runs)
                partials_run<Degree, Rational>(run, degree, nvb, dnvb, nv, q, dq, px, py, pz, s, s + nv, s + 2 * nv,
                                               s + 3 * nv, s + 4 * nv, s + 5 * nv);
            normals_row(nv, s, s + nv, s + 2 * nv, s + 3 * nv, s + 4 * nv, s + 5 * nv, g.normals.x.data() + offset,
                        g.normals.y.data() + offset, g.normals.z.data() + offset);
        }
    }
}

template <bool Rational>
[[gnu::always_inline]] inline void evaluate_rows_rational(GridJob& job) {
    switch (job.v_basis.degree) {
        case 1: evaluate_rows_for<1, Rational>(job); break;
        case 2: evaluate_rows_for<2, Rational>(job); break;
        case 3: evaluate_rows_for<3, Rational>(job); break;
        case 4: evaluate_rows_for<4, Rational>(job); break;
        case 5: evaluate_rows_for<5, Rational>(job); break;
        case 6: evaluate_rows_for<6, Rational>(job); break;
        case 7: evaluate_rows_for<7, Rational>(job); break;
        default: evaluate_rows_for<-1, Rational>(job); break;
    }
}

[[gnu::always_inline]] inline void evaluate_rows_inline(GridJob& job) {
    if (job.rational) evaluate_rows_rational<true>(job);
    else evaluate_rows_rational<false>(job);
}

// Function multiversioning by hand: the same loops compiled for the baseline and for AVX2 + FMA, the
// latter chosen at run time. (GCC's target_clones would do the same, but cloning templates and inline
// functions through ifunc resolvers is fragile across compilers; one explicit switch is not.)
void evaluate_rows_portable(GridJob& job) { evaluate_rows_inline(job); }

#if defined(__GNUC__) && defined(__x86_64__)
#define RATBEZ_GRID_HAVE_AVX2 1
[[gnu::target("avx2,fma")]] void evaluate_rows_avx2(GridJob& job) { evaluate_rows_inline(job); }

bool cpu_has_avx2_fma() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}
#else
#define RATBEZ_GRID_HAVE_AVX2 0
bool cpu_has_avx2_fma() { return false; }
#endif

std::atomic<bool> use_portable_kernels{false};

bool use_avx2() {
    static const bool available = cpu_has_avx2_fma();
    return available && !use_portable_kernels.load(std::memory_order_relaxed);
}

// S and its partials up to order two on the grid (GridOutput::second_partials). For the moderate grids it
// serves (curvature sampling), a plain loop: A2.3 (order 2) once per parameter, the u contraction of the
// net (and of its first and second u derivatives) once per row, then per point (q+1)-term sums of six
// homogeneous 4-vectors and the rational quotient rule (A4.4 to order two, as SurfaceEvaluator::jet).
void evaluate_second_partials(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                              SurfaceGrid& result) {
    const int p = surface.degree_u(), q = surface.degree_v();
    const std::size_t wu = to_size(p) + 1, wv = to_size(q) + 1;
    DirectionBasis u_spans, v_spans;  // only `first` is used: the span of every parameter
    compute_basis(p, surface.knots_u(), surface.rows(), us, false, u_spans);
    compute_basis(q, surface.knots_v(), surface.columns(), vs, false, v_spans);
    auto derivatives_of = [](int degree, std::span<const double> knots, const DirectionBasis& spans,
                             std::span<const double> ts) {
        const std::size_t width = to_size(degree) + 1;
        std::vector<double> ders(3 * width * ts.size());
        for (std::size_t k = 0; k < ts.size(); ++k)
            basis_function_derivatives(spans.first[k] + degree, ts[k], degree, knots, 2,
                                       std::span<double>(ders).subspan(3 * width * k, 3 * width));
        return ders;
    };
    const std::vector<double> nu = derivatives_of(p, surface.knots_u(), u_spans, us);
    const std::vector<double> nv = derivatives_of(q, surface.knots_v(), v_spans, vs);
    const std::size_t columns = to_size(surface.columns());
    const std::size_t c0 = to_size(v_spans.first.front()), c1 = to_size(v_spans.first.back()) + wv;
    const Vec4* net = surface.homogeneous_points().data();
    const bool rational = surface.is_rational();
    std::vector<Vec4> rows(3 * columns);  // Q, Q_u, Q_uu of the row's isocurve
    Vec4 *q0 = rows.data(), *q1 = q0 + columns, *q2 = q1 + columns;
    for (std::size_t i = 0; i < us.size(); ++i) {
        for (std::size_t c = c0; c < c1; ++c) q0[c] = q1[c] = q2[c] = Vec4{};
        const double* b = nu.data() + 3 * wu * i;
        for (std::size_t r = 0; r < wu; ++r) {
            const Vec4* row = net + (to_size(u_spans.first[i]) + r) * columns;
            for (std::size_t c = c0; c < c1; ++c) {
                q0[c] += b[r] * row[c];
                q1[c] += b[wu + r] * row[c];
                q2[c] += b[2 * wu + r] * row[c];
            }
        }
        for (std::size_t j = 0; j < vs.size(); ++j) {
            const double* e = nv.data() + 3 * wv * j;
            const std::size_t first = to_size(v_spans.first[j]);
            Vec4 a, au, av, auu, auv, avv;
            for (std::size_t l = 0; l < wv; ++l) {
                const std::size_t c = first + l;
                a += e[l] * q0[c];
                au += e[l] * q1[c];
                auu += e[l] * q2[c];
                av += e[wv + l] * q0[c];
                auv += e[wv + l] * q1[c];
                avv += e[2 * wv + l] * q0[c];
            }
            Vec3 s = weighted_part(a), su = weighted_part(au), sv = weighted_part(av);
            Vec3 suu = weighted_part(auu), suv = weighted_part(auv), svv = weighted_part(avv);
            if (rational) {
                // Leibniz on A = w S: S = A / w, S_u = (A_u - w_u S) / w, S_uu = (A_uu - 2 w_u S_u - w_uu S) / w, ...
                const double r = 1.0 / a.w;
                s = s * r;
                su = (su - s * au.w) * r;
                sv = (sv - s * av.w) * r;
                suu = (suu - su * (2 * au.w) - s * auu.w) * r;
                suv = (suv - su * av.w - sv * au.w - s * auv.w) * r;
                svv = (svv - sv * (2 * av.w) - s * avv.w) * r;
            }
            const std::size_t k = i * vs.size() + j;
            auto store = [k](GridVectors& out, const Vec3& value) {
                out.x[k] = value.x, out.y[k] = value.y, out.z[k] = value.z;
            };
            store(result.points, s);
            store(result.du, su);
            store(result.dv, sv);
            store(result.duu, suu);
            store(result.duv, suv);
            store(result.dvv, svv);
        }
    }
}

void resize(GridVectors& v, std::size_t size) {
    v.x.resize(size), v.y.resize(size), v.z.resize(size);
}
void clear(GridVectors& v) { v.x.clear(), v.y.clear(), v.z.clear(); }

}  // namespace

void select_grid_kernels(GridKernels kernels) {
    use_portable_kernels.store(kernels == GridKernels::portable, std::memory_order_relaxed);
}

const char* grid_kernels_name() { return use_avx2() ? "avx2+fma" : "portable"; }

std::vector<double> uniform_parameters(const Interval& domain, std::size_t count) {
    require(count >= 2, "count",
            [&] { return "a uniform grid needs at least 2 parameters (both ends), got " + std::to_string(count); });
    // An absurd count is an Error, not std::bad_alloc / std::length_error from the vector below.
    constexpr std::size_t max_count = std::size_t{1} << 27;
    require(count <= max_count, "count",
            [&] { return "at most " + std::to_string(max_count) + " parameters, got " + std::to_string(count); });
    require(std::isfinite(domain.min) && std::isfinite(domain.max) && domain.min < domain.max, "domain", [&] {
        return "must be a finite non-empty interval, got [" + exact_number(domain.min) + ", " + exact_number(domain.max) + "]";
    });
    std::vector<double> ts(count);
    const double width = domain.max - domain.min;
    const double steps = static_cast<double>(count - 1);
    // a + (b - a) k / n is monotone in k, but may round past b: clamp, and set both ends exactly.
    for (std::size_t k = 0; k < count; ++k)
        ts[k] = std::min(domain.max, domain.min + width * (static_cast<double>(k) / steps));
    ts.front() = domain.min;
    ts.back() = domain.max;
    return ts;
}

void evaluate_grid(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                   GridOutput output, SurfaceGrid& result) {
    evaluate_grid_blocks(surface, us, vs, output, std::max<std::size_t>(us.size(), 1), result,
                         [](std::size_t, const SurfaceGrid&) {});
}

void evaluate_grid_blocks(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                          GridOutput output, std::size_t block_rows, SurfaceGrid& block,
                          const std::function<void(std::size_t first_row, const SurfaceGrid& block)>& consume) {
    validate_parameters(us, surface.domain_u(), "us");
    validate_parameters(vs, surface.domain_v(), "vs");
    require(vs.empty() || us.size() <= std::numeric_limits<std::size_t>::max() / vs.size() / 8, "us", [&] {
        return "the grid of " + std::to_string(us.size()) + " x " + std::to_string(vs.size()) + " points is too large";
    });
    require(block_rows > 0, "block_rows", "must be positive");

    // Sizes `block` for `rows` rows of the grid.
    const bool second = output == GridOutput::second_partials;
    auto size_block = [&](std::size_t rows) {
        const std::size_t size = rows * vs.size();
        block.u_count = rows;
        block.v_count = vs.size();
        block.output = output;
        resize(block.points, size);
        if (output == GridOutput::partials || second) resize(block.du, size), resize(block.dv, size);
        else clear(block.du), clear(block.dv);
        if (second) resize(block.duu, size), resize(block.duv, size), resize(block.dvv, size);
        else clear(block.duu), clear(block.duv), clear(block.dvv);
        if (output == GridOutput::normals) resize(block.normals, size);
        else clear(block.normals);
    };
    if (us.empty() || vs.empty()) {
        size_block(us.size());
        consume(0, block);
        return;
    }
    if (second) {
        for (std::size_t first = 0; first < us.size(); first += block_rows) {
            const std::size_t rows = std::min(block_rows, us.size() - first);
            size_block(rows);
            evaluate_second_partials(surface, us.subspan(first, rows), vs, block);
            consume(first, block);
        }
        return;
    }

    // The bases of both directions and the v spans once for the whole grid; then block by block.
    GridJob job;
    job.surface = &surface;
    job.us = us;
    job.vs = vs;
    job.output = output;
    job.rational = surface.is_rational();
    job.result = &block;
    const bool derivatives = output != GridOutput::points;
    compute_basis(surface.degree_u(), surface.knots_u(), surface.rows(), us, derivatives, job.u_basis);
    compute_basis(surface.degree_v(), surface.knots_v(), surface.columns(), vs, derivatives, job.v_basis);
    job.runs = span_runs(job.v_basis);
    job.column_min = job.v_basis.first.front();
    job.column_max = job.v_basis.first.back() + surface.degree_v();
    job.q.resize(to_size(surface.columns()));
    if (derivatives) job.dq.resize(to_size(surface.columns()));
    if (output == GridOutput::normals) job.scratch.resize(6 * vs.size());

    for (std::size_t first = 0; first < us.size(); first += block_rows) {
        job.row_begin = first;
        job.row_end = first + std::min(block_rows, us.size() - first);
        size_block(job.row_end - first);
#if RATBEZ_GRID_HAVE_AVX2
        if (use_avx2()) evaluate_rows_avx2(job);
        else evaluate_rows_portable(job);
#else
        evaluate_rows_portable(job);
#endif
        if (output == GridOutput::normals) {
            // The points the vectorised pass marked degenerate (NaN), by the point-wise limit rule.
            GridVectors& n = block.normals;
            for (std::size_t i = first; i < job.row_end; ++i)
                for (std::size_t j = 0; j < vs.size(); ++j) {
                    const std::size_t k = (i - first) * vs.size() + j;
                    if (!std::isnan(n.x[k])) continue;
                    const Vec3 limit = surface.normal(us[i], vs[j]);
                    n.x[k] = limit.x, n.y[k] = limit.y, n.z[k] = limit.z;
                }
        }
        consume(first, block);
    }
}

SurfaceGrid evaluate_grid(const NurbsSurface& surface, std::span<const double> us, std::span<const double> vs,
                          GridOutput output) {
    SurfaceGrid result;
    evaluate_grid(surface, us, vs, output, result);
    return result;
}

SurfaceGrid evaluate_grid(const NurbsSurface& surface, std::size_t u_count, std::size_t v_count, GridOutput output) {
    require(u_count >= 2, "u_count",
            [&] { return "a uniform grid needs at least 2 parameters (both ends), got " + std::to_string(u_count); });
    require(v_count >= 2, "v_count",
            [&] { return "a uniform grid needs at least 2 parameters (both ends), got " + std::to_string(v_count); });
    const std::vector<double> us = uniform_parameters(surface.domain_u(), u_count);
    const std::vector<double> vs = uniform_parameters(surface.domain_v(), v_count);
    return evaluate_grid(surface, us, vs, output);
}

}  // namespace ratbez
