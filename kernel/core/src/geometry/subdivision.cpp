// The cuts between the certified pieces of weight lines (subdivision.hpp).
#include "geometry/subdivision.hpp"

namespace ratbez::detail {

std::vector<double> weight_cuts(const std::vector<std::vector<double>>& lines, int max_halvings) {
    std::vector<double> cuts{0.0};
    for_each_certified_piece(lines, [](double w) { return w; }, max_halvings,
                             [&](const std::vector<std::vector<double>>&, double, double b) { cuts.push_back(b); });
    return cuts;
}

}  // namespace ratbez::detail
