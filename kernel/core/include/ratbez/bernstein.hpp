#pragma once
// Bernstein polynomials B_{i,n}(u) = n!/(i!(n-i)!) u^i (1-u)^{n-i} (000 §1.3, Eq. 1.8).

#include <vector>

namespace ratbez {

// B_{i,n}(u) by the triangular recurrence of A1.2; 0 when i < 0 or i > n.
double bernstein(int i, int n, double u);

// All n+1 values B_{0,n}(u) .. B_{n,n}(u) at once (A1.3).
std::vector<double> all_bernstein(int n, double u);

// The k-th derivative of every B_{i,n} at u (003: B'_{i,n} = n (B_{i-1,n-1} - B_{i,n-1})), k >= 0.
std::vector<double> all_bernstein_derivatives(int n, int k, double u);

}  // namespace ratbez
