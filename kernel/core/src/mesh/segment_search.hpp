#pragma once
// Searching the fine polylines of a face's boundary (deviation.cpp): which side of a closed polyline in the plane
// a point lies on, and which segment of a polyline is nearest to a point, each without visiting every segment.
// A planar face of 991 holes' worth of boundary (a keyboard case) has tens of thousands; a scan of all of them
// for every sample of the mesh took 87% of its export. Not installed, not part of the public API.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The even-odd rule on closed polylines in the plane (x, y): the segments kept in bands of y, so that a ray from
// a point towards +x meets only those of the point's band. The segments, as (x0, y0, x1, y1), must close up
// exactly (each loop's last point its first).
class EvenOddBands {
public:
    explicit EvenOddBands(std::vector<std::array<double, 4>> segments = {});
    // Whether a ray from (x, y) towards +x crosses an odd number of segments.
    bool inside(double x, double y) const;

private:
    std::size_t band_of(double y) const;
    std::vector<std::array<double, 4>> segments_;
    double y_min_ = 0, y_max_ = 0;
    std::vector<std::vector<std::uint32_t>> bands_;
};

// The segment of a set nearest to a point, found through a uniform grid of the segments' middles searched in
// growing boxes (a scan for a few dozen). Ties go to the lowest index, as a scan in order would give them.
class NearestSegment {
public:
    struct Found {
        std::size_t index;  // into the segments given
        double fraction;    // along it from its start to the nearest point, in [0, 1]
        double squared_distance;
    };

    explicit NearestSegment(std::vector<std::array<Vec3, 2>> segments = {});
    // None when there are no segments.
    std::optional<Found> nearest(const Vec3& p) const;

private:
    std::array<int, 3> cell_of(const Vec3& p) const;
    std::size_t flat(const std::array<int, 3>& c) const;
    std::vector<std::array<Vec3, 2>> segments_;
    Vec3 lo_{}, hi_{};
    double cell_ = 1, half_length_ = 0, extent_ = 1;
    std::array<int, 3> dims_{1, 1, 1};
    std::vector<std::vector<std::uint32_t>> grid_;
};

}  // namespace ratbez::detail
