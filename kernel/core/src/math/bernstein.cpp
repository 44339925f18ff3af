// Bernstein polynomials B_{i,n}(u) = n!/(i!(n-i)!) u^i (1-u)^{n-i} (000 §1.3, Eq. 1.8), evaluated by the
// triangular recurrence P1.6 rather than by the closed form: the recurrence only ever forms convex
// combinations of non-negative numbers, so it is stable for every degree and never overflows n!.

#include "ratbez/bernstein.hpp"

#include <string>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {

namespace {

// The degree of every basis is bounded like every curve's (limits.hpp): A1.2 is O(n^2).
void require_degree(int n) { limits::require_degree(n, "n"); }

}  // namespace

double bernstein(int i, int n, double u) {
    require_degree(n);
    require_in_domain(u, 0.0, 1.0, "u");
    // P1.6: B_{i,n} == 0 outside 0 <= i <= n.
    if (i < 0 || i > n) return 0.0;

    // A1.2: run the recurrence of P1.6 on the column of Table 1.1 that starts with a single 1 at n - i.
    const auto size = static_cast<std::size_t>(n) + 1;
    std::vector<double> column(size, 0.0);
    column[static_cast<std::size_t>(n - i)] = 1.0;
    const double one_minus_u = 1.0 - u;
    for (std::size_t k = 1; k < size; ++k)
        for (std::size_t j = size - 1; j >= k; --j) column[j] = one_minus_u * column[j] + u * column[j - 1];
    return column[size - 1];
}

std::vector<double> all_bernstein(int n, double u) {
    require_degree(n);
    require_in_domain(u, 0.0, 1.0, "u");

    // A1.3: build degree j from degree j - 1 in place (Table 1.2); `saved` carries u * B_{k,j-1} into
    // B_{k+1,j} = (1-u) B_{k+1,j-1} + u B_{k,j-1}.
    const auto size = static_cast<std::size_t>(n) + 1;
    std::vector<double> values(size, 0.0);
    values[0] = 1.0;
    const double one_minus_u = 1.0 - u;
    for (std::size_t j = 1; j < size; ++j) {
        double saved = 0.0;
        for (std::size_t k = 0; k < j; ++k) {
            const double previous = values[k];
            values[k] = saved + one_minus_u * previous;
            saved = u * previous;
        }
        values[j] = saved;
    }
    return values;
}

std::vector<double> all_bernstein_derivatives(int n, int k, double u) {
    require_degree(n);
    limits::require_derivative_order(k, "k");
    require_in_domain(u, 0.0, 1.0, "u");

    const auto size = static_cast<std::size_t>(n) + 1;
    std::vector<double> derivatives(size, 0.0);
    if (k > n) return derivatives;  // a degree-n polynomial has no (n+1)-th derivative

    // P1.7 applied k times: B^(k)_{i,n} = n!/(n-k)! sum_{j=0..k} (-1)^{k-j} C(k,j) B_{i-j,n-k}
    // (the k-th backward difference of the degree n-k basis), with B_{r,n-k} = 0 outside 0..n-k.
    const std::vector<double> lower = all_bernstein(n - k, u);
    double falling_factorial = 1.0;  // n (n-1) ... (n-k+1)
    for (int r = 0; r < k; ++r) falling_factorial *= static_cast<double>(n - r);

    for (int i = 0; i <= n; ++i) {
        double sum = 0.0;
        for (int j = 0; j <= k; ++j) {
            const int r = i - j;
            if (r < 0 || r > n - k) continue;
            const double sign = ((k - j) % 2 == 0) ? 1.0 : -1.0;
            sum += sign * detail::binomial(k, j) * lower[static_cast<std::size_t>(r)];
        }
        derivatives[static_cast<std::size_t>(i)] = falling_factorial * sum;
    }
    return derivatives;
}

}  // namespace ratbez
