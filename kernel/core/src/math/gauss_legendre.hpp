#pragma once
// Gauss–Legendre rules on [0, 1]: n nodes integrate every polynomial of degree 2n - 1 exactly. The rules
// of the integration engine (analysis/cubature.hpp) and of span_rule.hpp. Not installed, not part of the
// public API.

#include <vector>

namespace ratbez::detail {

// Nodes and weights on [0, 1] (nodes by Newton's method on P_n to machine precision).
struct GaussRule {
    std::vector<double> nodes, weights;
};
// The rule of `points` nodes, 1 <= points <= 32 (else Error naming `points`); computed once, kept.
const GaussRule& gauss_legendre(int points);

}  // namespace ratbez::detail
