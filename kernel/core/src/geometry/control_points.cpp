// The homogeneous control points shared by every curve and surface class (control_points.hpp).
#include "ratbez/control_points.hpp"

#include <cmath>
#include <utility>

namespace ratbez {

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
    const auto rows = static_cast<std::size_t>(rows_), columns = static_cast<std::size_t>(columns_);
    std::vector<std::vector<Vec3>> net(rows, std::vector<Vec3>(columns));
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < columns; ++j) net[i][j] = point_at(i * columns + j);
    return net;
}

std::vector<std::vector<double>> ControlNet::weights() const {
    const auto rows = static_cast<std::size_t>(rows_), columns = static_cast<std::size_t>(columns_);
    std::vector<std::vector<double>> net(rows, std::vector<double>(columns));
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < columns; ++j) net[i][j] = weight_at(i * columns + j);
    return net;
}

}  // namespace ratbez
