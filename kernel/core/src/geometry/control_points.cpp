// The homogeneous control points shared by every curve and surface class (control_points.hpp).
#include "ratbez/control_points.hpp"

#include <cmath>
#include <utility>

namespace ratbez {
namespace {

// A row-major table as nested rows, net[i][j] = entry(i * columns + j).
template <class Entry>
auto nested(int rows, int columns, const Entry& entry) {
    using T = decltype(entry(std::size_t{0}));
    const auto r = static_cast<std::size_t>(rows), c = static_cast<std::size_t>(columns);
    std::vector<std::vector<T>> net(r, std::vector<T>(c));
    for (std::size_t i = 0; i < r; ++i)
        for (std::size_t j = 0; j < c; ++j) net[i][j] = entry(i * c + j);
    return net;
}

}  // namespace

HomogeneousPoints::HomogeneousPoints(std::vector<Vec4> pw, bool rational, int weight_exponent)
    : pw_(std::move(pw)), rational_(rational), weight_exponent_(weight_exponent) {}

// The scale 2^weight_exponent is a power of two, so undoing it is exact.
double HomogeneousPoints::weight_at(std::size_t k) const { return std::ldexp(pw_[k].w, -weight_exponent_); }

std::vector<Vec3> ControlPolygon::points() const {
    std::vector<Vec3> result(pw_.size());
    for (std::size_t k = 0; k < pw_.size(); ++k) result[k] = point_at(k);
    return result;
}

std::vector<double> ControlPolygon::weights() const {
    std::vector<double> result(pw_.size());
    for (std::size_t k = 0; k < pw_.size(); ++k) result[k] = weight_at(k);
    return result;
}

ControlNet::ControlNet(int rows, int columns, std::vector<Vec4> pw, bool rational, int weight_exponent)
    : HomogeneousPoints(std::move(pw), rational, weight_exponent), rows_(rows), columns_(columns) {}

std::vector<std::vector<Vec3>> ControlNet::points() const {
    return nested(rows_, columns_, [this](std::size_t k) { return point_at(k); });
}

std::vector<std::vector<double>> ControlNet::weights() const {
    return nested(rows_, columns_, [this](std::size_t k) { return weight_at(k); });
}

}  // namespace ratbez
