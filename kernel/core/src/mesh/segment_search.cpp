// Searching boundary polylines (segment_search.hpp).

#include "mesh/segment_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace ratbez::detail {

namespace {

// Below this many segments a scan of them all is as quick as the search structures, which cost memory (a Voron
// LED channel mount of 1,120 faces, each with a few dozen segments, measured no faster through them).
constexpr std::size_t kScanBelow = 64;

}  // namespace

// ------------------------------------------------------------------------------------ the even-odd rule

EvenOddBands::EvenOddBands(std::vector<std::array<double, 4>> segments) : segments_(std::move(segments)) {
    if (segments_.empty()) return;
    y_min_ = std::numeric_limits<double>::infinity(), y_max_ = -y_min_;
    for (const auto& s : segments_) y_min_ = std::min({y_min_, s[1], s[3]}), y_max_ = std::max({y_max_, s[1], s[3]});
    if (segments_.size() < kScanBelow) return;
    // About the square root of the segments' number of bands: each holds about as many segments.
    bands_.assign(std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(static_cast<double>(segments_.size()))), 1, 4096), {});
    for (std::size_t k = 0; k < segments_.size(); ++k) {
        const auto [lo, hi] = std::minmax(segments_[k][1], segments_[k][3]);
        for (std::size_t b = band_of(lo), end = band_of(hi); b <= end; ++b) bands_[b].push_back(static_cast<std::uint32_t>(k));
    }
}

std::size_t EvenOddBands::band_of(double y) const {
    const double f = (y - y_min_) / std::max(y_max_ - y_min_, 1e-300);
    return std::min(bands_.size() - 1, static_cast<std::size_t>(std::max(0.0, f) * static_cast<double>(bands_.size())));
}

bool EvenOddBands::inside(double x, double y) const {
    // A segment the ray crosses spans y, so it lies in y's band; outside all bands no segment spans y.
    if (segments_.empty() || !(y >= y_min_ && y <= y_max_)) return false;
    bool inside = false;
    const auto cross = [&](const std::array<double, 4>& s) {
        const auto& [x0, y0, x1, y1] = s;
        if ((y0 <= y) != (y1 <= y) && x < x0 + (y - y0) / (y1 - y0) * (x1 - x0)) inside = !inside;
    };
    if (bands_.empty()) {
        for (const auto& s : segments_) cross(s);
    } else {
        for (const std::uint32_t k : bands_[band_of(y)]) cross(segments_[k]);
    }
    return inside;
}

// ------------------------------------------------------------------------------------ the nearest segment

NearestSegment::NearestSegment(std::vector<std::array<Vec3, 2>> segments) : segments_(std::move(segments)) {
    if (segments_.size() < kScanBelow) return;
    lo_ = hi_ = 0.5 * (segments_.front()[0] + segments_.front()[1]);
    for (const auto& [a, b] : segments_) {
        const Vec3 m = 0.5 * (a + b);
        lo_ = {std::min(lo_.x, m.x), std::min(lo_.y, m.y), std::min(lo_.z, m.z)};
        hi_ = {std::max(hi_.x, m.x), std::max(hi_.y, m.y), std::max(hi_.z, m.z)};
        half_length_ = std::max(half_length_, 0.5 * distance(a, b));
    }
    extent_ = std::max({hi_.x - lo_.x, hi_.y - lo_.y, hi_.z - lo_.z, 1e-300});
    const double cells = std::max(1.0, std::cbrt(static_cast<double>(segments_.size())));
    cell_ = std::max(extent_ / cells, 2 * half_length_);
    for (int a = 0; a < 3; ++a) dims_[static_cast<std::size_t>(a)] = 1 + static_cast<int>(((&hi_.x)[a] - (&lo_.x)[a]) / cell_);
    grid_.assign(static_cast<std::size_t>(dims_[0]) * static_cast<std::size_t>(dims_[1]) * static_cast<std::size_t>(dims_[2]), {});
    for (std::size_t k = 0; k < segments_.size(); ++k)
        grid_[flat(cell_of(0.5 * (segments_[k][0] + segments_[k][1])))].push_back(static_cast<std::uint32_t>(k));
}

std::array<int, 3> NearestSegment::cell_of(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int a = 0; a < 3; ++a)
        c[static_cast<std::size_t>(a)] =
            std::clamp(static_cast<int>(std::floor(((&p.x)[a] - (&lo_.x)[a]) / cell_)), 0, dims_[static_cast<std::size_t>(a)] - 1);
    return c;
}

std::size_t NearestSegment::flat(const std::array<int, 3>& c) const {
    return (static_cast<std::size_t>(c[0]) * static_cast<std::size_t>(dims_[1]) + static_cast<std::size_t>(c[1])) *
               static_cast<std::size_t>(dims_[2]) + static_cast<std::size_t>(c[2]);
}

std::optional<NearestSegment::Found> NearestSegment::nearest(const Vec3& p) const {
    if (segments_.empty() || !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) return std::nullopt;
    Found best{0, 0, std::numeric_limits<double>::infinity()};
    bool found = false;  // so that a first segment at infinite distance is still taken
    const auto consider = [&](std::uint32_t k) {
        const auto& [a, b] = segments_[k];
        const Vec3 e = b - a;
        const double length2 = dot(e, e);
        const double f = length2 > 0 ? std::clamp(dot(p - a, e) / length2, 0.0, 1.0) : 0.0;
        const Vec3 d = a + e * f - p;
        const double d2 = dot(d, d);
        if (!found || d2 < best.squared_distance || (d2 == best.squared_distance && k < best.index)) best = {k, f, d2}, found = true;
    };
    if (segments_.size() < kScanBelow) {
        for (std::size_t k = 0; k < segments_.size(); ++k) consider(static_cast<std::uint32_t>(k));
        return best;
    }
    // Every segment lies within half_length_ of its middle: a box of half-width r + half_length_ around p holds
    // every segment closer than r, ties included. The box grows until the nearest found lies within r, or it holds
    // the whole grid.
    for (double r = cell_;; r *= 2) {
        const Vec3 reach{r + half_length_, r + half_length_, r + half_length_};
        const std::array<int, 3> from = cell_of(p - reach), to = cell_of(p + reach);
        for (int x = from[0]; x <= to[0]; ++x)
            for (int y = from[1]; y <= to[1]; ++y)
                for (int z = from[2]; z <= to[2]; ++z)
                    for (const std::uint32_t k : grid_[flat({x, y, z})]) consider(k);
        const bool whole = from == std::array<int, 3>{0, 0, 0} && to == std::array<int, 3>{dims_[0] - 1, dims_[1] - 1, dims_[2] - 1};
        if (best.squared_distance <= r * r || whole) break;
    }
    return best;
}

}  // namespace ratbez::detail
