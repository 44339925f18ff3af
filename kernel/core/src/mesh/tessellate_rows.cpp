// Staggered rows for faces closed along u (tessellate_rows.hpp).

#include "mesh/tessellate_rows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <cstring>
#include <unordered_map>

#include "mesh/triangle_grid.hpp"
#include "ratbez/surface_grid.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The second fundamental form around a place, as magnitudes (the largest over the curvature samples a strip
// touches), and whether L and N agree in sign at all of them.
struct Bend {
    double L = 0, N = 0, M = 0;
    bool definite = true;
};

// The peak error of the staggered triangle (0, 0), (h, 0), (h / 2, k) for magnitudes L, N and no twist.
double staggered_peak(double L, double N, double h, double k) {
    const double a = N * k * k, b = L * h * h / 4;
    if (b >= a || a == 0) return L * h * h / 8;
    return (a + b) * (a + b) / (8 * a);
}

// The width of the staggered triangle's errors on a saddle without twist (magnitudes L, N): its extremes lie on
// its edges (an indefinite quadratic has no interior extremum), the base's midpoint at one sign and the slanted
// edges' at (L h^2 / 4 - N k^2) / 8 on the other once N k^2 passes L h^2 / 4.
double saddle_width(double L, double N, double h, double k) {
    return (L * h * h + std::max(0.0, N * k * k - L * h * h / 4)) / 8;
}

// The width of a strip triangle's errors (highest minus lowest) with base h along u and height k along v.
double error_width(const Bend& b, double h, double k, bool staggered) {
    if (staggered && b.definite) return staggered_peak(b.L, b.N, h, k) + b.M * h * k / 4;
    if (staggered && b.M == 0) return saddle_width(b.L, b.N, h, k);
    return (b.L * h * h + b.N * k * k) / 8 + b.M * h * k / 4;
}

// The largest x in (0, upper] whose width(x) is at most `width`, by bisection (width grows with x): the
// twisted case, which has no closed form; the closed form without the twist bounds it from above.
template <class Width>
double largest_within(Width&& width_of, double width, double upper) {
    if (width_of(upper) <= width) return upper;
    double low = 0, high = upper;
    for (int step = 0; step < 40; ++step) {
        const double mid = 0.5 * (low + high);
        (width_of(mid) <= width ? low : high) = mid;
    }
    return low;
}

// The largest side x of a grid cell x by y whose bound (P x^2 + Q y^2) / 8 + T x y / 4 stays within `width`:
// P and Q the bends along x and y, T the twist (magnitudes); 0 when y alone exceeds it, infinite where
// nothing bends along x. A strip whose rows drift is bounded so along u and along v alike.
double cell_side(double P, double Q, double T, double y, double width) {
    const double rest = 8 * width - (Q > 0 ? Q * y * y : 0.0);  // an infinite y where Q vanishes adds nothing
    if (rest <= 0 || (T > 0 && !std::isfinite(y))) return 0;
    if (P > 0) return (-T * y + std::sqrt(T * T * y * y + P * rest)) / P;
    return T > 0 ? rest / (2 * T * y) : kInfinity;
}

// The largest strip height k whose triangles of base h err within `width` (0: none; infinite: any).
double strip_height(const Bend& b, double h, double width, bool staggered) {
    double k = kInfinity;
    if (staggered && b.definite) {
        if (b.L * h * h > 8 * width) return 0;
        // The larger root of (N k^2 + L h^2 / 4)^2 = 8 N k^2 width (the staggered peak inside the triangle).
        if (b.N > 0) k = (std::sqrt(8 * b.N * width) + std::sqrt(std::max(8 * b.N * width - b.N * b.L * h * h, 0.0))) / (2 * b.N);
    } else if (staggered && b.M == 0) {
        if (b.L * h * h > 8 * width) return 0;
        return b.N > 0 ? std::sqrt((8 * width - 0.75 * b.L * h * h) / b.N) : kInfinity;
    } else {
        return cell_side(b.N, b.L, b.M, h, width);
    }
    if (b.M == 0 || h == 0) return k;
    const double twist_bound = 4 * width / (b.M * h);
    return largest_within([&](double x) { return error_width(b, h, x, true); }, width, std::min(k, twist_bound));
}

// The largest base h of a strip of height k whose triangles err within `width`.
double row_spacing(const Bend& b, double k, double width, bool staggered) {
    const double nk2 = b.N > 0 ? b.N * k * k : 0.0;  // an infinite k where N vanishes adds nothing
    if (!std::isfinite(k) && b.M > 0) return 0;
    double h = kInfinity;
    if (staggered && b.definite) {
        if (nk2 > 8 * width) return 0;
        if (b.L > 0) {
            h = b.N > 0 && k >= std::sqrt(2 * width / b.N)
                    ? std::sqrt(4 * (std::sqrt(8 * b.N * width) * k - nk2) / b.L)
                    : std::sqrt(8 * width / b.L);
        }
    } else if (staggered && b.M == 0) {
        if (nk2 > 8 * width) return 0;
        if (b.L > 0) return std::sqrt(nk2 >= 2 * width ? (8 * width - nk2) / (0.75 * b.L) : 8 * width / b.L);
    } else {
        return cell_side(b.L, b.N, b.M, k, width);
    }
    if (b.M == 0 || k == 0) return h;
    const double twist_bound = 4 * width / (b.M * k);
    return largest_within([&](double x) { return error_width(b, x, k, true); }, width, std::min(h, twist_bound));
}

// The strip height of the best triangle for the bend: equilateral in H's metric where L and N agree
// (k' = sqrt(4.5 width)), a square cell on a saddle (k' = sqrt(4 width)); infinite where nothing bends along v.
double ideal_height(const Bend& b, double width) {
    const double bend = std::max(b.N, b.M);
    return bend > 0 ? std::sqrt((b.definite ? 4.5 : 4.0) * width / bend) : kInfinity;
}

// The spacing of row r's samples around u: a row off the seam spans it with the interval from its last sample
// round to its first.
double rail_spacing(const RowGrid& rows, std::size_t r, double u, const Interval& domain) {
    const std::vector<double>& w = rows.u[r];
    if (rows.on_seam[r]) return spacing_at(w, u);
    if (u <= w.front() || u >= w.back()) return w.front() + (domain.max - domain.min) - w.back();
    return spacing_at(w, u);
}

bool is_pole_row(const SurfacePlan& plan, const RowGrid& rows, std::size_t j) {
    return (j == 0 && plan.sides[side_slot(Side::v_min)].degenerate) ||
           (j + 1 == rows.v.size() && plan.sides[side_slot(Side::v_max)].degenerate);
}

// The march that plans the rows (tessellate_rows.hpp).
class RowPlanner {
public:
    RowPlanner(const SurfacePlan& plan, const CurvatureSamples& c, double target, std::span<const Tightening> tight)
        : plan_(plan), c_(c), width_(2 * kOffsetShare * target), tight_(tight) {}

    // The march starts at the row that needs the most samples and goes both ways, so that every zone starts at
    // what its first row needs and shrinks (a zone that grows must start above its need to last); a face
    // closed along v starts and ends at its seam, which is one row.
    RowGrid plan(double max_triangles) {
        const Interval dv{c_.vs.front(), c_.vs.back()};
        const bool closed_v = !plan_.sides[side_slot(Side::v_min)].degenerate &&
                              plan_.sides[side_slot(Side::v_min)].edge == plan_.sides[side_slot(Side::v_max)].edge;
        needs_.clear();
        for (double v : c_.vs) needs_.push_back(needed(v));
        // Rows that need as much up to rounding (a sphere's around its equator, whose bands all reach the
        // equator's row) are one choice, the middle one, whatever the rounding at the solid's scale.
        double start_v = dv.min;
        if (!closed_v) {
            const double most = *std::max_element(needs_.begin(), needs_.end());
            std::vector<double> near_most;
            for (std::size_t j = 0; j < c_.vs.size(); ++j)
                if (needs_[j] >= most * (1 - 1e-6)) near_most.push_back(c_.vs[j]);
            start_v = near_most[near_most.size() / 2];
        }
        Row start{start_v, {}, false, 0, zone_count(start_v, 1.0)};
        start.pole = (start_v == dv.min && plan_.sides[side_slot(Side::v_min)].degenerate) ||
                     (start_v == dv.max && plan_.sides[side_slot(Side::v_max)].degenerate);
        start.u = start.pole ? ends() : place(start_v, start.count, 0);
        if (!start.pole && start.count == 0) return {};
        double triangles = 0;
        std::vector<Row> down, up;
        std::vector<char> down_kind, up_kind;
        std::vector<const Row*> all;
        const Row top{dv.max, start.u, false, start.phase, start.count};  // a closed v's seam again, at its end
        if (closed_v) {
            // From the seam both ways to the row that needs the fewest samples, where the two marches meet: the
            // strip that closes them (a transition, likely) is cheapest there. Ties: the first such row.
            const double least = *std::min_element(needs_.begin() + 1, needs_.end() - 1);
            std::size_t meet = 1;
            while (needs_[meet] > least * (1 + 1e-6)) ++meet;
            if (!march(start, +1, c_.vs[meet], nullptr, up, up_kind, triangles, max_triangles) ||
                !march(top, -1, c_.vs[meet], up.empty() ? &start : &up.back(), down, down_kind, triangles, max_triangles))
                return {};
            all.push_back(&start);
            for (const Row& r : up) all.push_back(&r);
            for (std::size_t k = down.size() - 1; k-- > 0;) all.push_back(&down[k]);  // the last is up's last
            all.push_back(&top);
            up_kind.insert(up_kind.end(), down_kind.rbegin(), down_kind.rend());
            down_kind.clear();
        } else {
            if (!march(start, -1, dv.min, nullptr, down, down_kind, triangles, max_triangles) ||
                !march(start, +1, dv.max, nullptr, up, up_kind, triangles, max_triangles))
                return {};
            for (auto r = down.rbegin(); r != down.rend(); ++r) all.push_back(&*r);
            all.push_back(&start);
            for (const Row& r : up) all.push_back(&r);
        }
        RowGrid rows;
        for (std::size_t j = 0; j < all.size(); ++j) {
            const Row& r = *all[j];
            // A row moved off the seam by its phase closes across it (row_rail), unless it is a side (an edge).
            const bool on_seam = r.pole || r.phase == 0 || j == 0 || j + 1 == all.size();
            rows.v.push_back(r.v);
            rows.u.push_back(on_seam ? r.u : std::vector<double>(r.u.begin() + 1, r.u.end() - 1));
            rows.on_seam.push_back(on_seam ? 1 : 0);
        }
        rows.staggered.assign(down_kind.rbegin(), down_kind.rend());
        rows.staggered.insert(rows.staggered.end(), up_kind.begin(), up_kind.end());
        index_seam(rows);
        if (rows.v.size() < 2 || rows.v.size() - 1 < static_cast<std::size_t>(plan_.min_segments[1])) return {};
        return rows;
    }

private:
    struct Row {
        double v;
        std::vector<double> u;
        bool pole;
        double phase;       // 0 or 0.5: where the row's samples sit in its zone's spacing
        std::size_t count;  // the zone's count: samples between the seam's two ends, phase 0
    };

    std::vector<double> ends() const { return {c_.us.front(), c_.us.back()}; }

    // The rows after `start` (not included) in direction `sign` to `end`, every crease a row, and the kind of
    // each strip (staggered: the model's triangle). The last row is `close_to` (copied, at `end`) when given: the
    // march closes onto it once the strip fits. False when nothing fits or the triangles (added to `triangles`)
    // exceed the budget.
    bool march(const Row& start, double sign, double end, const Row* close_to, std::vector<Row>& rows,
               std::vector<char>& kinds, double& triangles, double max_triangles) {
        const Interval dv{c_.vs.front(), c_.vs.back()};
        if (start.v == end) return true;
        const bool to_pole = (end == dv.max && plan_.sides[side_slot(Side::v_max)].degenerate) ||
                             (end == dv.min && plan_.sides[side_slot(Side::v_min)].degenerate);
        std::vector<double> stops;  // the creases beyond the start, in the march's order, then the end
        for (double c : plan_.creases[1])
            if (sign * (c - start.v) > 0 && sign * (end - c) > 0) stops.push_back(c);
        if (sign < 0) std::reverse(stops.begin(), stops.end());
        stops.push_back(end);
        const auto reached = [&](double v, double b) { return sign * (v - b) >= 0; };
        const auto push = [&](Row next, const Row& r) {
            triangles += static_cast<double>(r.pole ? 1 : r.u.size()) + static_cast<double>(next.pole ? 1 : next.u.size()) - 2;
            kinds.push_back(r.pole || next.pole || (next.phase != r.phase && next.count == r.count) ? 1 : 0);
            rows.push_back(std::move(next));
            return triangles <= max_triangles && rows.size() <= 100'000;
        };
        for (double b : stops) {
            const bool pole_end = to_pole && b == end;
            while (true) {
                const Row r = rows.empty() ? start : rows.back();
                if (pole_end && !r.pole && sign * (b - r.v) <= height(r, nullptr, b, true)) {
                    if (!push(Row{b, ends(), true, 0, 0}, r)) return false;
                    break;
                }
                // The last strip ends at `close_to`'s row: it closes once it fits.
                const bool closing = close_to != nullptr && b == end;
                if (closing) {
                    Row last = *close_to;
                    last.v = b;
                    const bool staggered = last.phase != r.phase && last.count == r.count;
                    if (sign * (b - r.v) <= height(r, &last.u, b, staggered)) {
                        if (!push(std::move(last), r)) return false;
                        break;
                    }
                }
                Row next = step(r, b, sign);
                if (!(sign * (next.v - r.v) > 0) || !std::isfinite(next.v)) return false;
                if ((pole_end || closing) && reached(next.v, b)) {  // the last strip did not fit: a row on the way
                    next.v = 0.5 * (r.v + b);
                    next.u = place(next.v, next.count, next.phase);
                } else if (reached(next.v, b)) {
                    next.v = b;
                    next.u = place(b, next.count, next.phase);
                }
                const bool at_stop = next.v == b;
                if (!push(std::move(next), r)) return false;
                if (at_stop) break;
            }
        }
        return true;
    }

    // The bends of every u sample over a strip from v0 to v1: the largest of the curvature sample rows inside it
    // and of the values at its two ends, linear between the sample rows around them; definite where every
    // sample row it touches is.
    const std::vector<Bend>& band(double v0, double v1) {
        const std::vector<double>& vs = c_.vs;
        if (v0 > v1) std::swap(v0, v1);
        // The sample rows around each end (plain variables, not structured bindings: clang does not let the lambda
        // below capture those).
        const IntervalPosition low = locate_in(vs, v0), high = locate_in(vs, v1);
        const std::size_t lo = low.k, hi = high.k + 1;
        const double f0 = low.f, f1 = high.f;
        bends_.assign(c_.us.size(), Bend{});
        for (std::size_t i = 0; i < c_.us.size(); ++i) {
            Bend& b = bends_[i];
            // Each form's largest value of either sign over the strip; where one changes sign within it (an
            // inflection of the profile, the top of a torus) its triangles err both ways by those amounts.
            const auto take = [&](const std::vector<double>& field) {
                double up = 0, down = 0;
                const auto see = [&](double x) { (x > 0 ? up : down) = std::max(x > 0 ? up : down, std::abs(x)); };
                see((1 - f0) * field[c_.at(i, lo)] + f0 * field[c_.at(i, lo + 1)]);
                see((1 - f1) * field[c_.at(i, hi - 1)] + f1 * field[c_.at(i, hi)]);
                for (std::size_t j = lo + 1; j < hi; ++j)
                    if (vs[j] > v0 && vs[j] < v1) see(field[c_.at(i, j)]);
                return std::pair{up, down};
            };
            const auto [L_up, L_down] = take(c_.L);
            const auto [N_up, N_down] = take(c_.N);
            const auto [M_up, M_down] = take(c_.M);
            b.L = L_up + L_down;
            b.N = N_up + N_down;
            b.M = std::max(M_up, M_down);
            if (b.M <= 1e-9 * (b.L + b.N)) b.M = 0;
            // Definite: L and N each of one sign over the strip, the same sign where both bend. Values within
            // rounding of 0 (the pole row's) have no sign.
            const double noise = 1e-9 * (b.L + b.N);
            const auto sign_of = [&](double up, double down) {
                if (up > noise && down > noise) return 2;  // both signs
                return up > noise ? 1 : down > noise ? -1 : 0;
            };
            const int sl = sign_of(L_up, L_down), sn = sign_of(N_up, N_down);
            b.definite = sl != 2 && sn != 2 && (sl == 0 || sn == 0 || sl == sn);
        }
        return bends_;
    }

    // Samples per unit u the row at v needs at each u sample: where its strips have their ideal height, with
    // the bends over both of them (the curvature in parameters grows fast towards a pole, and a row too coarse
    // for the strip beyond it leaves that strip no height). Where the strip needs it less, a row needs more
    // samples and the transition strips between zones less height: both ways cost more.
    const std::vector<double>& ideal_density(double v) {
        if (v == density_v_ && !density_.empty()) return density_;  // asked again for the same row
        density_v_ = v;
        double k = kInfinity;
        const double near = width(v, v);
        for (const Bend& bend : band(v, v)) k = std::min(k, ideal_height(bend, near));
        const double reach = std::isfinite(k) ? k : 0.0;
        const double low = std::max(v - reach, c_.vs.front()), high = std::min(v + reach, c_.vs.back());
        const double w = width(low, high);
        const std::vector<Bend>& bends = band(low, high);
        density_.resize(bends.size());
        for (std::size_t i = 0; i < bends.size(); ++i) {
            const double h = row_spacing(bends[i], ideal_height(bends[i], w), w, true);
            density_[i] = h > 0 ? 1 / h : kInfinity;
        }
        return density_;
    }

    // The samples the row at v needs (at least the three that enclose anything).
    double needed(double v) {
        const std::vector<double>& d = ideal_density(v);
        double total = 0;
        for (std::size_t i = 0; i + 1 < d.size(); ++i) total += 0.5 * (d[i] + d[i + 1]) * (c_.us[i + 1] - c_.us[i]);
        return std::max(total, 3.0);
    }

    // A zone's count for the row at v: what it needs, `spread` times over (a zone that grows starts above it).
    std::size_t zone_count(double v, double spread) { return count_of(needed(v) * spread); }
    static std::size_t count_of(double samples) {
        const double n = std::ceil(samples * (1 - 1e-12));
        return std::isfinite(n) && n < 1e9 ? static_cast<std::size_t>(n) : 0;
    }

    // The `count` samples of a row at v (plus the seam's second end when the phase moves them off it), spaced by
    // its ideal density: equal shares of its integral, the k-th at (k + phase) shares from u's start.
    std::vector<double> place(double v, std::size_t count, double phase) {
        const std::vector<double>& us = c_.us;
        const std::vector<double>& d = ideal_density(v);
        std::vector<double> rho(us.size() - 1), cumulative(us.size(), 0.0);
        double largest = 0;
        for (std::size_t i = 0; i + 1 < us.size(); ++i) largest = std::max(largest, std::max(d[i], d[i + 1]));
        for (std::size_t i = 0; i + 1 < us.size(); ++i) {
            // A row that needs nothing somewhere (a flat stretch) still spreads its samples a little there.
            rho[i] = std::isfinite(largest) && largest > 0 ? std::max(0.5 * (d[i] + d[i + 1]), 1e-3 * largest) : 1.0;
            cumulative[i + 1] = cumulative[i] + rho[i] * (us[i + 1] - us[i]);
        }
        const double total = cumulative.back();
        std::vector<double> out{us.front()};
        std::size_t i = 0;
        for (std::size_t k = 0; k < count; ++k) {
            const double at = (static_cast<double>(k) + phase) / static_cast<double>(count) * total;
            if (at <= 0) continue;
            while (i + 2 < us.size() && cumulative[i + 1] < at) ++i;
            out.push_back(std::min(us[i] + (at - cumulative[i]) / rho[i], us[i + 1]));
        }
        out.push_back(us.back());
        return merge_params(std::move(out), us.front(), us.back());
    }

    // The largest height of the strip from row r to v1 (at most; the bends of that band), whose other row has
    // the samples `next` (none: as r), staggered or not.
    double height(const Row& r, const std::vector<double>* next, double v1, bool staggered) {
        const std::vector<Bend>& bends = band(r.v, v1);
        const double w = width(r.v, v1);
        double k = kInfinity;
        for (std::size_t i = 0; i < bends.size(); ++i) {
            const double u = c_.us[i];
            double h = r.pole ? 0.0 : spacing_at(r.u, u);
            if (next != nullptr) h = std::max(h, spacing_at(*next, u));
            k = std::min(k, strip_height(bends[i], h, w, staggered));
        }
        return k;
    }

    // The row after r towards b: the zone's count staggered while it fits the row's need within
    // kZoneSpread, else a transition to the count the row needs.
    Row step(const Row& r, double b, double sign) {
        const auto ahead = [&](double k) { return std::isfinite(k) && sign * (b - r.v) > k ? r.v + sign * k : b; };
        double omega = 0;
        if (!r.pole) {
            Row keep{r.v, {}, false, 0.5 - r.phase, r.count};
            // The tallest strip its own band allows: height() over a taller band is never more, so the row's own
            // height is an upper bound and the height over the band that reaches it a lower one; three bisections
            // between them. (The lower bound alone plans a strip whose bend grows along the march for the bend at
            // the far end of a band it does not reach: the vase's middle strips erred at 0.85 of the target.)
            double k = height(r, nullptr, r.v, true);
            if (k > 0) {
                const auto height_to = [&](double reach) {
                    keep.v = ahead(reach);
                    keep.u = place(keep.v, keep.count, keep.phase);
                    return height(r, &keep.u, keep.v, true);
                };
                double high = k, low = std::min(k, height_to(k));
                low = std::min(low, height_to(low));
                for (int round = 0; round < 3 && low < high * (1 - 1e-3); ++round) {
                    const double middle = 0.5 * (low + high);
                    (height_to(middle) >= middle ? low : high) = middle;
                }
                k = low;
            }
            if (k > 0) {
                keep.v = ahead(k);
                omega = static_cast<double>(r.count) / needed(keep.v);
                if (omega >= 1 && omega <= kZoneSpread) {
                    keep.u = place(keep.v, keep.count, keep.phase);
                    return keep;
                }
            }
        }
        // A transition: up to what the row needs times kZoneSpread when the rows grow (from a pole too), so that
        // the new zone lasts; down to what it needs when they shrink.
        // A growing zone starts no higher than the most any row ahead needs (a torus's rows grow back to its seam).
        double spread = 1.0, most_ahead = 0;
        if (r.pole || omega < 1) {
            for (std::size_t j = 0; j < c_.vs.size(); ++j)
                if (sign * (c_.vs[j] - r.v) > 0) most_ahead = std::max(most_ahead, needs_[j]);
            spread = kZoneSpread;
        }
        double k = kInfinity;
        for (const Bend& bend : band(r.v, r.v)) k = std::min(k, ideal_height(bend, width(r.v, r.v)));
        // The strip is tried at that height and shrunk to what its model allows until it fits (the bend grows
        // with the band: near a pole the rows' curvature in parameters grows fast).
        double reach = sign * (ahead(k) - r.v);
        const double smallest = 1e-9 * (c_.vs.back() - c_.vs.front());
        Row next{r.v, {}, false, 0, 0};
        for (int round = 0; round < 40; ++round) {
            next.v = r.v + sign * reach;
            const double need = needed(next.v);
            const double wanted = spread > 1 ? std::min(need * spread, std::max(need, most_ahead)) : need;
            next.count = std::max<std::size_t>(3, count_of(wanted));
            if (next.count > 10'000'000) break;
            next.u = place(next.v, next.count, 0);
            k = height(r, &next.u, next.v, r.pole);
            if (k >= reach * (1 - 1e-9)) {
                // Back at the zone's count (its need fell within the strip): the zone goes on, staggered.
                if (!r.pole && next.count == r.count) next.phase = 0.5 - r.phase, next.u = place(next.v, next.count, next.phase);
                return next;
            }
            reach = k > 0 ? k : 0.5 * reach;
            if (!(reach > smallest)) break;
        }
        return Row{r.v, {}, false, 0, 0};  // nothing fits: no rows
    }

    const SurfacePlan& plan_;
    const CurvatureSamples& c_;
    // The span the errors of a strip from v0 to v1 may have: twice the largest offset, tightened where a check
    // found the model optimistic.
    double width(double v0, double v1) const {
        double factor = 1;
        for (const Tightening& t : tight_)
            if (t.v1 >= std::min(v0, v1) && t.v0 <= std::max(v0, v1)) factor = std::min(factor, t.factor);  // touching counts: a row serves both strips
        return factor * width_;
    }

    const double width_;
    std::span<const Tightening> tight_;
    std::vector<Bend> bends_;
    std::vector<double> needs_;  // needed() at every curvature sample row
    std::vector<double> density_;
    double density_v_ = kInfinity;
};

// The errors (mesh minus surface, vertices on the surface) at curvature sample (i, jc) of strip j, signed as the
// bend: the model's triangle where the strip is staggered, a grid cell's where its rows drift. (`c` may be
// the curvature sampled on the rows themselves, row_offset_field.)
ErrorSpan strip_errors(const SurfacePlan& plan, const CurvatureSamples& c, std::size_t i, std::size_t jc, std::size_t j) {
    const RowGrid& rows = plan.rows;
    const double u = c.us[i];
    const double k = rows.v[j + 1] - rows.v[j];
    double h = 0;
    for (std::size_t r : {j, j + 1})
        if (!is_pole_row(plan, rows, r)) h = std::max(h, rail_spacing(rows, r, u, plan.face->surface().domain_u()));
    const std::size_t at = c.at(i, jc);
    const double L = c.L[at], N = c.N[at];
    const double M = std::abs(c.M[at]) > 1e-9 * (std::abs(L) + std::abs(N)) ? c.M[at] : 0.0;  // a rounding's twist is none
    // The errors of a grid cell of h x k (and of any strip whose rows drift against each other).
    const auto cell = [&](double base) {
        ErrorSpan span;
        for (double term : {L * base * base / 8, N * k * k / 8, -M * base * k / 4}) (term < 0 ? span.below : span.above) += term;
        return span;
    };
    if (!rows.staggered[j]) return cell(h);
    ErrorSpan span;
    if (L * N >= 0) {
        const double peak = staggered_peak(std::abs(L), std::abs(N), h, k);
        (L + N < 0 ? span.below : span.above) = L + N < 0 ? -peak : peak;
        span.below -= std::abs(M) * h * k / 8;
        span.above += std::abs(M) * h * k / 8;
    } else if (M == 0) {  // a saddle: the base's midpoint and the slanted edges' (saddle_width)
        for (double value : {L * h * h / 8, (L * h * h / 4 + N * k * k) / 8})
            span.below = std::min(span.below, value), span.above = std::max(span.above, value);
    } else {
        span = cell(h);
    }
    // At the seam every row has a vertex, so between staggered rows its column is a line of right triangles
    // (legs half a spacing and the strip's height) beside the staggered ones: its vertices take the centre of
    // both (the vertical chord alone sags N k^2 / 8, more than any edge of a staggered triangle).
    if ((i == 0 || i + 1 == c.us.size()) && rows.on_seam[j] && rows.on_seam[j + 1]) {
        const ErrorSpan right = cell(h / 2);
        span.below = std::min(span.below, right.below);
        span.above = std::max(span.above, right.above);
    }
    return span;
}

// The outcome of check_rows: the worst error over the target, and what to bisect.
struct RowCheck {
    double worst_ratio = 0;
    std::vector<double> strip_ratio;       // per strip: its worst error over the target
    std::vector<std::vector<char>> split;  // per row, per sample interval
    std::vector<char> split_strip;         // per strip: a row in its middle
};

// The chord's sag from the surface between two parameter points (surface points at both ends, the
// middle's against the chord's middle): which way to bisect is the surface's business, not the offsets'.
// A parameter of a rail wrapped into u's domain (a row off the seam starts at its last sample less the period).
double wrapped(double u, const Interval& domain) { return u < domain.min ? u + (domain.max - domain.min) : u; }

double chord_sag(const SurfaceEvaluator& s, double u0, double v0, double u1, double v1) {
    const Interval d = s.domain_u();
    return distance(s.point(wrapped(0.5 * (u0 + u1), d), 0.5 * (v0 + v1)),
                    0.5 * (s.point(wrapped(u0, d), v0) + s.point(wrapped(u1, d), v1)));
}

// The strips that passed a check, by everything their check depends on (both rows' parameters and vertices):
// a plan made again differs from the last one only here and there, and its other strips need no new check.
class PassedStrips {
public:
    // The strip's data, kept for the next lookup or insert.
    void describe(const RowGrid& rows, const std::vector<std::size_t>& starts, const std::vector<Vec3>& corners, std::size_t j) {
        data_.clear();
        for (std::size_t r : {j, j + 1}) {
            data_.push_back(rows.v[r]);
            data_.push_back(static_cast<double>(rows.u[r].size()));
            data_.push_back(static_cast<double>(rows.on_seam[r]));
            for (std::size_t k = 0; k < rows.u[r].size(); ++k) {
                const Vec3& p = corners[starts[r] + k];
                data_.insert(data_.end(), {rows.u[r][k], p.x, p.y, p.z});
            }
        }
    }
    bool contains() const {
        const auto it = passed_.find(hash());
        return it != passed_.end() && it->second == data_;
    }
    void insert() { passed_[hash()] = data_; }

private:
    std::uint64_t hash() const {  // FNV-1a over the doubles' bits
        std::uint64_t h = 1469598103934665603ull;
        for (double x : data_) {
            std::uint64_t bits = 0;
            std::memcpy(&bits, &x, sizeof bits);
            h = (h ^ bits) * 1099511628211ull;
        }
        return h;
    }
    std::vector<double> data_;
    std::unordered_map<std::uint64_t, std::vector<double>> passed_;
};

RowCheck check_rows(const SurfacePlan& plan, const std::vector<Vec3>& corners, const TessellationSettings& settings,
                    PassedStrips& passed) {
    const RowGrid& rows = plan.rows;
    const SurfaceEvaluator& s = *plan.evaluator;
    const ParameterBox domain{s.domain_u(), s.domain_v()};
    const std::vector<std::size_t> starts = row_starts(rows);
    const std::size_t count = rows.v.size();
    RowCheck check;
    check.split.resize(count);
    for (std::size_t j = 0; j < count; ++j) check.split[j].assign(rows.u[j].size() - (rows.on_seam[j] ? 1 : 0), 0);
    check.split_strip.assign(count - 1, 0);
    check.strip_ratio.assign(count - 1, 0);
    const double period = domain.u.max - domain.u.min;
    std::vector<RailPoint> points;
    const auto rail = [&](std::size_t j, std::vector<CellVertex>& out) {
        out.clear();
        const bool pole = is_pole_row(plan, rows, j);
        row_rail(rows, starts, j, period, points);
        for (const RailPoint& x : points) {
            const auto id = static_cast<MeshVertexId>(pole ? starts[j] : x.vertex);
            out.push_back(CellVertex{x.u, rows.v[j], corners[x.vertex], id});
        }
    };
    std::vector<CellVertex> bottom, top, lower, upper;
    std::vector<CellTriangle> triangles;
    std::vector<double> errors;
    for (std::size_t j = 0; j + 1 < count; ++j) {
        if (j % 16 == 15) settings.poll();
        passed.describe(rows, starts, corners, j);
        if (passed.contains()) continue;
        rail(j, bottom);
        rail(j + 1, top);
        triangles.clear();
        triangulate_strip(bottom, top, lower, upper, triangles);
        strip_errors(s, plan.face->surface(), triangles, rows.v[j], rows.v[j + 1], plan.target, errors);
        for (std::size_t n = 0; n < triangles.size(); ++n) {
            const CellTriangle& t = triangles[n];
            const double ratio = errors[n] / plan.target;
            check.worst_ratio = std::max(check.worst_ratio, ratio);
            check.strip_ratio[j] = std::max(check.strip_ratio[j], ratio);
            if (ratio <= 1) continue;
            // Two vertices on one rail (the base), one on the other (the apex; a pole takes each base
            // vertex's u for its edge to it).
            const auto on_lower = [&](const CellVertex* x) { return x >= lower.data() && x < lower.data() + lower.size(); };
            std::size_t apex = 0;
            for (std::size_t q = 0; q < 3; ++q)
                if (on_lower(t[q]) != on_lower(t[(q + 1) % 3]) && on_lower(t[q]) != on_lower(t[(q + 2) % 3])) apex = q;
            const CellVertex &a = *t[(apex + 1) % 3], &b = *t[(apex + 2) % 3], &p = *t[apex];
            const double base = chord_sag(s, a.u, a.v, b.u, b.v);
            const double slant = std::max(chord_sag(s, a.u, a.v, p.free == CellVertex::Free::u ? a.u : p.u, p.v),
                                          chord_sag(s, b.u, b.v, p.free == CellVertex::Free::u ? b.u : p.u, p.v));
            if (base >= 0.5 * slant) {
                const std::size_t r = on_lower(&a) ? j : j + 1;
                const std::vector<CellVertex>& on = on_lower(&a) ? lower : upper;
                const auto ka = static_cast<std::size_t>(&a - on.data()), kb = static_cast<std::size_t>(&b - on.data());
                check.split[r][std::min(ka, kb)] = 1;
            }
            if (slant >= 0.5 * base) check.split_strip[j] = 1;
        }
        if (check.strip_ratio[j] <= 1) passed.insert();
    }
    // The polylines along the sides against their curves (a crease's curve is the mesh's edge, which no
    // triangle's check sees): the first and last rows, and the seam.
    const auto side_ratio = [&](std::size_t strip, const Vec3& a, const Vec3& b, auto&& surface_at) {
        double error = 0;
        for (double f : {0.25, 0.5, 0.75}) error = std::max(error, point_segment_distance(surface_at(f), a, b));
        const double ratio = error / plan.target;
        check.worst_ratio = std::max(check.worst_ratio, ratio);
        check.strip_ratio[strip] = std::max(check.strip_ratio[strip], ratio);
        return ratio > 1;
    };
    for (std::size_t j : {std::size_t{0}, count - 1}) {
        if (is_pole_row(plan, rows, j)) continue;
        const std::vector<double>& u = rows.u[j];
        for (std::size_t k = 0; k + 1 < u.size(); ++k)
            if (side_ratio(j == 0 ? 0 : count - 2, corners[starts[j] + k], corners[starts[j] + k + 1],
                           [&](double f) { return s.point(u[k] + f * (u[k + 1] - u[k]), rows.v[j]); }))
                check.split[j][k] = 1;
    }
    for (std::size_t j = 0; j + 1 < count; ++j)
        if (rows.on_seam[j] && rows.on_seam[j + 1] &&  // between rows off it, the seam is no chord of the mesh
            side_ratio(j, corners[starts[j]], corners[starts[j + 1]],
                       [&](double f) { return s.point(rows.u[j].front(), rows.v[j] + f * (rows.v[j + 1] - rows.v[j])); }))
            check.split_strip[j] = 1;
    return check;
}

// Bisects the marked sample intervals of every row, then puts a row in the middle of every marked strip with
// the samples of its finer row (the strip between the two copies is a tensor row of cells). A face closed
// along v keeps its first and last rows (one edge) alike.
bool apply_splits(const SurfacePlan& plan, RowGrid& rows, const RowCheck& check) {
    bool any = false;
    const bool closed_v = !plan.sides[side_slot(Side::v_min)].degenerate &&
                          plan.sides[side_slot(Side::v_min)].edge == plan.sides[side_slot(Side::v_max)].edge;
    const Interval d = plan.face->surface().domain_u();
    const double period = d.max - d.min;
    for (std::size_t j = 0; j < rows.v.size(); ++j) {
        if (is_pole_row(plan, rows, j)) continue;
        std::vector<double>& u = rows.u[j];
        std::vector<double> added = u;
        if (rows.on_seam[j]) {
            for (std::size_t k = 0; k + 1 < u.size(); ++k)
                if (check.split[j][k]) added.push_back(0.5 * (u[k] + u[k + 1]));
        } else {
            // The rail's first interval runs across the seam, from the last sample less the period.
            for (std::size_t k = 0; k < u.size(); ++k)
                if (check.split[j][k]) added.push_back(wrapped(0.5 * ((k == 0 ? u.back() - period : u[k - 1]) + u[k]), d));
        }
        if (added.size() == u.size()) continue;
        if (rows.on_seam[j]) {
            u = merge_params(std::move(added), u.front(), u.back());
        } else {
            std::sort(added.begin(), added.end());
            added.erase(std::unique(added.begin(), added.end()), added.end());
            u = std::move(added);
        }
        any = true;
    }
    if (closed_v) {
        std::vector<double> both = rows.u.front();
        both.insert(both.end(), rows.u.back().begin(), rows.u.back().end());
        rows.u.front() = rows.u.back() = merge_params(std::move(both), rows.u.front().front(), rows.u.front().back());
    }
    for (std::size_t j = rows.v.size() - 1; j-- > 0;) {
        if (!check.split_strip[j]) continue;
        const bool low_finer = !is_pole_row(plan, rows, j) &&
                               (is_pole_row(plan, rows, j + 1) || rows.u[j].size() >= rows.u[j + 1].size());
        const std::size_t source = low_finer ? j : j + 1;
        const std::vector<double> samples = rows.u[source];
        const char on_seam = rows.on_seam[source];
        rows.v.insert(rows.v.begin() + static_cast<std::ptrdiff_t>(j + 1), 0.5 * (rows.v[j] + rows.v[j + 1]));
        rows.u.insert(rows.u.begin() + static_cast<std::ptrdiff_t>(j + 1), samples);
        rows.on_seam.insert(rows.on_seam.begin() + static_cast<std::ptrdiff_t>(j + 1), on_seam);
        // The copy and its source make a tensor row; the copy and the other row keep the strip's kind.
        const char kind = rows.staggered[j];
        rows.staggered.insert(rows.staggered.begin() + static_cast<std::ptrdiff_t>(j), kind);
        rows.staggered[low_finer ? j : j + 1] = 0;
        any = true;
    }
    index_seam(rows);
    return any;
}

}  // namespace

bool rows_apply(const SurfacePlan& plan, const TessellationSettings& settings) {
    const SideMap &low = plan.sides[side_slot(Side::u_min)], &high = plan.sides[side_slot(Side::u_max)];
    return plan.straddle && settings.angle_rad == 0 && !low.degenerate && low.edge == high.edge &&
           plan.creases[0].size() == 2;
}

RowGrid plan_rows(const SurfacePlan& plan, const CurvatureSamples& c, double target, double max_triangles,
                  std::span<const Tightening> tight) {
    return RowPlanner(plan, c, target, tight).plan(max_triangles);
}

double row_triangles(const SurfacePlan& plan, const RowGrid& rows) {
    double count = 0;
    // A rail off the seam has its last vertex twice (row_rail).
    const auto rail_size = [&](std::size_t j) {
        return is_pole_row(plan, rows, j) ? 1.0 : static_cast<double>(rows.u[j].size() + (rows.on_seam[j] ? 0 : 1));
    };
    for (std::size_t j = 0; j + 1 < rows.v.size(); ++j) count += rail_size(j) + rail_size(j + 1) - 2;
    return count;
}

std::vector<std::size_t> row_starts(const RowGrid& rows) {
    std::vector<std::size_t> starts(rows.v.size() + 1, 0);
    for (std::size_t j = 0; j < rows.v.size(); ++j) starts[j + 1] = starts[j] + rows.u[j].size();
    return starts;
}

void row_rail(const RowGrid& rows, const std::vector<std::size_t>& starts, std::size_t j, double period,
              std::vector<RailPoint>& out) {
    out.clear();
    const std::vector<double>& u = rows.u[j];
    if (!rows.on_seam[j]) out.push_back({u.back() - period, starts[j + 1] - 1});
    for (std::size_t k = 0; k < u.size(); ++k) out.push_back({u[k], starts[j] + k});
}

void index_seam(RowGrid& rows) {
    rows.seam_v.clear();
    for (std::size_t j = 0; j < rows.v.size(); ++j)
        if (rows.on_seam[j]) rows.seam_v.push_back(rows.v[j]);
}

OffsetField row_offset_field(const SurfacePlan& plan, const CurvatureSamples& c) {
    // The field lives on the rows themselves: the curvature at every row (linear between the sample rows), each
    // row's vertices at the centre of the errors of the two strips they belong to. Between curvature samples,
    // interpolated offsets centred no strip: near the vase's rim, eight strips to a sample interval erred up to
    // 1.36 times the target at 1e-3 before the check sent them back.
    const RowGrid& rows = plan.rows;
    CurvatureSamples at_rows;
    at_rows.us = c.us;
    at_rows.vs = rows.v;
    const std::size_t n = rows.v.size(), last = c.vs.size() - 1;
    // A pole's sample row has no tangent plane (its values are 0): it takes the next row's, as in offset_field.
    const std::array<bool, 4> collapsed = collapsed_sides(plan);
    const auto sample_row = [&](std::size_t b) {
        if (b == 0 && collapsed[side_slot(Side::v_min)]) return std::size_t{1};
        if (b == last && collapsed[side_slot(Side::v_max)]) return last - 1;
        return b;
    };
    for (auto* field : {&at_rows.L, &at_rows.N, &at_rows.M, &at_rows.k_max}) field->resize(c.us.size() * n);
    for (std::size_t j = 0; j < n; ++j) {
        const auto [b, f] = locate_in(c.vs, rows.v[j]);
        for (std::size_t i = 0; i < c.us.size(); ++i) {
            const std::size_t lo = c.at(i, sample_row(b)), hi = c.at(i, sample_row(b + 1)), k = at_rows.at(i, j);
            at_rows.L[k] = (1 - f) * c.L[lo] + f * c.L[hi];
            at_rows.N[k] = (1 - f) * c.N[lo] + f * c.N[hi];
            at_rows.M[k] = (1 - f) * c.M[lo] + f * c.M[hi];
            at_rows.k_max[k] = (1 - f) * c.k_max[lo] + f * c.k_max[hi];
        }
    }
    const auto row_errors = [&](std::size_t i, std::size_t j) {
        ErrorSpan span;
        for (std::size_t strip : {j - 1, j})
            if (strip < n - 1) {  // j - 1 wraps below 0: none
                const ErrorSpan e = strip_errors(plan, at_rows, i, j, strip);
                span.below = std::min(span.below, e.below);
                span.above = std::max(span.above, e.above);
            }
        return span;
    };
    return offset_field(at_rows, row_errors, collapsed, plan.max_offset(), plan.target, plan.straddle);
}

void interior_row_points(const SurfacePlan& plan, std::vector<Vec3>& out) {
    const RowGrid& rows = plan.rows;
    const NurbsSurface& surface = plan.face->surface();
    const std::vector<std::size_t> starts = row_starts(rows);
    out.resize(starts.back());
    thread_local SurfaceGrid batch;
    thread_local std::vector<Vec3> normals;
    normals.assign(out.size(), Vec3{});
    bool all_normals = true;
    for (std::size_t j = 0; j < rows.v.size(); ++j) {
        const double v = rows.v[j];
        evaluate_grid(surface, rows.u[j], std::span<const double>(&v, 1), GridOutput::partials, batch);
        for (std::size_t k = 0; k < rows.u[j].size(); ++k) {
            const std::size_t at = starts[j] + k;
            out[at] = batch.points[k];
            const Vec3 su = batch.du[k], sv = batch.dv[k], n = cross(su, sv);
            const double scale2 = dot(su, su) + dot(sv, sv);
            if (dot(n, n) > 1e-12 * scale2 * scale2) normals[at] = n / norm(n);
            else if (!is_pole_row(plan, rows, j) && all_normals) {
                try {
                    normals[at] = surface.normal(rows.u[j][k], v);
                } catch (const Error&) {
                    all_normals = false;  // a point without a tangent plane (nor a limit normal): none is moved
                }
            }
        }
    }
    if (!all_normals) return;
    thread_local std::vector<Vec3> on_surface;
    on_surface = out;
    for (std::size_t j = 0; j < rows.v.size(); ++j) {
        if (is_pole_row(plan, rows, j)) continue;
        const std::vector<double>& u = rows.u[j];
        for (std::size_t k = 0; k < u.size(); ++k) {
            const std::size_t at = starts[j] + k;
            const Vec3 p = on_surface[at];
            // The room its neighbours leave (offset_room): along the row, and the nearest in u on the rows
            // either side.
            double gap = kInfinity;
            auto near = [&](std::size_t other) {
                const double d = distance(p, on_surface[other]);
                if (d > 0) gap = std::min(gap, d);
            };
            if (k > 0) near(at - 1);
            if (k + 1 < u.size()) near(at + 1);
            for (std::size_t r : {j - 1, j + 1}) {
                if (r >= rows.v.size()) continue;
                const std::vector<double>& w = rows.u[r];
                const auto q = static_cast<std::size_t>(std::lower_bound(w.begin(), w.end(), u[k]) - w.begin());
                if (q < w.size()) near(starts[r] + q);
                if (q > 0) near(starts[r] + q - 1);
            }
            const double reach = offset_room(gap, plan.max_offset());
            out[at] = p + normals[at] * std::clamp(plan.offsets.at(u[k], rows.v[j]), -reach, reach);
        }
    }
}

RowRefinement refine_rows(SurfacePlan& plan, const CurvatureSamples& c, const TessellationSettings& settings,
                          const GridPoints& points, bool rescale) {
    std::vector<Tightening> tight;
    PassedStrips passed;
    std::vector<Vec3> corners;
    bool changed = false, bisected = false;
    for (int iteration = 0; iteration < 24; ++iteration) {
        settings.poll();
        if (const double at_least = kRowsAtLeast * row_triangles(plan, plan.rows); at_least > static_cast<double>(settings.max_triangles))
            throw TooFine(at_least, settings.max_triangles);
        points(plan, corners);
        const RowCheck check = check_rows(plan, corners, settings, passed);
        if (check.worst_ratio <= 1) return changed ? RowRefinement::changed : RowRefinement::unchanged;
        if (rescale && iteration == 0 && check.worst_ratio > kStraddleGiveUp) return RowRefinement::given_up;
        if (rescale && !bisected && iteration < 3 && check.worst_ratio < kStraddleGiveUp) {
            // Planned again with the span lowered where the strips failed, by their ratio (the model is
            // a little optimistic in places: where the bend changes between curvature samples, on saddles).
            const RowGrid& rows = plan.rows;
            const std::size_t before = tight.size();  // the factors in place when these strips were planned
            for (std::size_t j = 0; j + 1 < rows.v.size(); ++j) {
                if (check.strip_ratio[j] <= 1) continue;
                double factor = 1;
                for (std::size_t t = 0; t < before; ++t)
                    if (tight[t].v1 > rows.v[j] && tight[t].v0 < rows.v[j + 1]) factor = std::min(factor, tight[t].factor);
                // The strips move when planned again: the strip's neighbours' stretch is tightened with it.
                const double k = rows.v[j + 1] - rows.v[j];
                tight.push_back({rows.v[j] - k, rows.v[j + 1] + k, factor * 0.99 / check.strip_ratio[j]});
            }
            RowGrid again = plan_rows(plan, c, plan.target, static_cast<double>(settings.max_triangles) / kRowsAtLeast, tight);
            if (again.empty()) return RowRefinement::given_up;
            plan.rows = std::move(again);
        } else if (apply_splits(plan, plan.rows, check)) {
            bisected = true;
        } else {
            return RowRefinement::given_up;
        }
        changed = true;
        // Rows are worth it only while they need fewer triangles than the grid they were chosen over.
        if (row_triangles(plan, plan.rows) >= triangles_at_least(plan, plan.grid.u.size(), plan.grid.v.size()))
            return RowRefinement::given_up;
        plan.offsets = row_offset_field(plan, c);
    }
    return RowRefinement::given_up;
}

}  // namespace ratbez::detail
