#include "analysis/span_rule.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "math/gauss_legendre.hpp"
#include "ratbez/bspline_basis.hpp"

namespace ratbez::detail {
namespace {

// One direction of the rule: for every Gauss node of every non-empty span, the span index k (the node's
// basis functions are N_{k-p} .. N_k), N and N' there (A2.3) and the node's weight times the span's length.
struct Nodes {
    int degree = 0;
    std::vector<int> spans;
    std::vector<double> basis;  // per node: p + 1 values, then p + 1 first derivatives
    std::vector<double> weights;

    const double* values(std::size_t node) const { return basis.data() + node * 2 * static_cast<std::size_t>(degree + 1); }
    const double* derivatives(std::size_t node) const { return values(node) + degree + 1; }
};

Nodes nodes_on_spans(int degree, std::span<const double> knots, int points) {
    Nodes nodes{degree, {}, {}, {}};
    const GaussRule& rule = gauss_legendre(points);
    const int count = static_cast<int>(knots.size()) - degree - 1;  // control points; the domain is [u_p, u_count]
    const std::size_t per_node = 2 * static_cast<std::size_t>(degree + 1);
    const std::size_t most_nodes = static_cast<std::size_t>(std::max(count - degree, 0)) * rule.nodes.size();
    nodes.spans.reserve(most_nodes);
    nodes.weights.reserve(most_nodes);
    nodes.basis.reserve(most_nodes * per_node);
    for (int k = degree; k < count; ++k) {
        const double a = knots[static_cast<std::size_t>(k)], b = knots[static_cast<std::size_t>(k) + 1];
        if (!(b > a)) continue;
        for (std::size_t g = 0; g < rule.nodes.size(); ++g) {
            nodes.spans.push_back(k);
            nodes.weights.push_back(rule.weights[g] * (b - a));
            nodes.basis.resize(nodes.basis.size() + per_node);
            basis_function_derivatives(k, a + (b - a) * rule.nodes[g], degree, knots, 1,
                                       std::span<double>(nodes.basis).last(per_node));
        }
    }
    return nodes;
}

constexpr std::array<double, 2> kUnitKnots{0.0, 1.0};

}  // namespace

SpanNet span_net(const NurbsSurface& surface) {
    return SpanNet{surface.degree_u(), surface.degree_v(), surface.knots_u(), surface.knots_v(),
                   surface.homogeneous_points(), surface.columns()};
}

SpanNet span_net(const NurbsCurve& curve) {
    return SpanNet{curve.degree(), 0, curve.knots(), kUnitKnots, curve.homogeneous_points(), 1};
}

double control_weight_ratio(std::span<const Vec4> points) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const Vec4& p : points) {
        lo = std::min(lo, p.w);
        hi = std::max(hi, p.w);
    }
    return hi / lo;
}

double span_rule(const SpanNet& net, int points_u, int points_v, const SpanIntegrand& f) {
    const Nodes u = nodes_on_spans(net.degree_u, net.knots_u, points_u);
    const Nodes v = nodes_on_spans(net.degree_v, net.knots_v, points_v);
    const int p = net.degree_u, q = net.degree_v;
    const std::size_t rows = net.points.size() / static_cast<std::size_t>(net.columns);
    // Every control row summed in v at the current v node: the row's homogeneous point and its v-derivative.
    std::vector<Vec4> row_point(rows), row_slope(rows);
    double sum = 0;
    for (std::size_t b = 0; b < v.spans.size(); ++b) {
        const double* m = v.values(b);
        const double* dm = v.derivatives(b);
        const std::size_t first_column = static_cast<std::size_t>(v.spans[b] - q);
        for (std::size_t i = 0; i < rows; ++i) {
            const Vec4* row = net.points.data() + i * static_cast<std::size_t>(net.columns) + first_column;
            Vec4 h, hv;
            for (int j = 0; j <= q; ++j) {
                h += row[j] * m[j];
                hv += row[j] * dm[j];
            }
            row_point[i] = h;
            row_slope[i] = hv;
        }
        double line = 0;
        for (std::size_t a = 0; a < u.spans.size(); ++a) {
            const double* n = u.values(a);
            const double* dn = u.derivatives(a);
            const std::size_t first_row = static_cast<std::size_t>(u.spans[a] - p);
            Vec4 h, hu, hv;
            for (int i = 0; i <= p; ++i) {
                h += row_point[first_row + static_cast<std::size_t>(i)] * n[i];
                hu += row_point[first_row + static_cast<std::size_t>(i)] * dn[i];
                hv += row_slope[first_row + static_cast<std::size_t>(i)] * n[i];
            }
            line += u.weights[a] * f(project_first_derivatives(h, hu, hv));
        }
        sum += v.weights[b] * line;
    }
    return sum;
}

}  // namespace ratbez::detail
