// Power basis curves C(u) = sum a_i u^i (000 §1.2, Eq. 1.5), Horner's rule (A1.1), power basis surfaces
// by Horner2 (A1.6), and the exact change of basis between power and Bézier form of Exercise 1.14.

#include "ratbez/power_basis.hpp"

#include <string>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {

namespace {

using detail::binomial;  // exact while C(n, k) < 2^53 (every n <= 56)

// Control points or power coefficients of a degree-n curve: as many as a Bézier curve may have.
void require_finite_points(const std::vector<Vec3>& points, const std::string& argument) {
    require(!points.empty(), argument, "must not be empty");
    limits::require_bezier_count(points.size(), argument, "entries");
    for (std::size_t i = 0; i < points.size(); ++i)
        require(is_finite(points[i]), argument,
                [&] { return "element " + std::to_string(i) + " has a non-finite coordinate"; });
}

// The converted points or coefficients must be finite: M's entries reach 3^n, so points near the double
// range can convert past it.
const std::vector<Vec3>& require_finite_result(const std::vector<Vec3>& result, const std::string& argument) {
    for (const Vec3& p : result)
        require(is_finite(p), argument, "the converted values are beyond double range (the input is too large)");
    return result;
}

}  // namespace

// Horner's rule is a plain polynomial evaluation, so it accepts any finite u: Exercise 1.9 evaluates a
// power basis curve on [-1, 1], and reparameterisation (Exercise 1.15) needs other intervals too.
// Any finite u, so the value can leave the double range (u = 1e200 on a cubic): an Error, not inf.
double horner(const std::vector<double>& coefficients, double u) {
    require(!coefficients.empty(), "coefficients", "must not be empty");
    limits::require_bezier_count(coefficients.size(), "coefficients", "entries");
    require_finite(coefficients, "coefficients");
    require_finite(u, "u");
    // A1.1
    double value = coefficients.back();
    for (std::size_t i = coefficients.size() - 1; i-- > 0;) value = value * u + coefficients[i];
    require(std::isfinite(value), "u", [&] { return "the value at u = " + detail::number(u) + " is beyond double range"; });
    return value;
}

Vec3 horner(const std::vector<Vec3>& coefficients, double u) {
    require_finite_points(coefficients, "coefficients");
    require_finite(u, "u");
    // A1.1 on each coordinate at once.
    Vec3 value = coefficients.back();
    for (std::size_t i = coefficients.size() - 1; i-- > 0;) value = value * u + coefficients[i];
    require(is_finite(value), "u", [&] { return "the value at u = " + detail::number(u) + " is beyond double range"; });
    return value;
}

Vec3 horner(const std::vector<std::vector<Vec3>>& coefficients, double u, double v) {
    require(!coefficients.empty(), "coefficients", "must not be empty");
    require_finite(u, "u");
    require_finite(v, "v");
    const std::size_t columns = coefficients.front().size();
    for (std::size_t i = 0; i < coefficients.size(); ++i)
        require(coefficients[i].size() == columns, "coefficients", [&] {
            return "row " + std::to_string(i) + " has " + std::to_string(coefficients[i].size()) + " entries, row 0 has " +
                   std::to_string(columns);
        });
    // A1.6: Horner1 on each row a[i][] at v0 gives b[i], then Horner1 on b at u0.
    std::vector<Vec3> b;
    b.reserve(coefficients.size());
    for (const std::vector<Vec3>& row : coefficients) b.push_back(horner(row, v));
    return horner(b, u);
}

std::vector<std::vector<double>> bezier_to_power_matrix(int n) {
    // Bounded like every degree (limits.hpp): its entries reach 3^n, past the double range beyond n = 646,
    // and are exact only while C(n, i) C(i, j) < 2^53.
    limits::require_degree(n, "n");
    // B_{j,n}(u) = C(n,j) u^j (1-u)^{n-j} = sum_i (-1)^{i-j} C(n,j) C(n-j,i-j) u^i, and
    // C(n,j) C(n-j,i-j) = C(n,i) C(i,j): the coefficient of u^i in B_{j,n} (Exercise 1.14).
    const auto size = static_cast<std::size_t>(n) + 1;
    std::vector<std::vector<double>> m(size, std::vector<double>(size, 0.0));
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= i; ++j) {
            const double sign = ((i - j) % 2 == 0) ? 1.0 : -1.0;
            m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = sign * binomial(n, i) * binomial(i, j);
        }
    return m;
}

std::vector<Vec3> bezier_to_power(const std::vector<Vec3>& control_points) {
    require_finite_points(control_points, "control_points");
    // [a_i] = M [P_i] (Exercise 1.14).
    const auto m = bezier_to_power_matrix(static_cast<int>(control_points.size()) - 1);
    std::vector<Vec3> coefficients(control_points.size());
    for (std::size_t i = 0; i < coefficients.size(); ++i)
        for (std::size_t j = 0; j <= i; ++j) coefficients[i] += m[i][j] * control_points[j];
    return require_finite_result(coefficients, "control_points");
}

std::vector<Vec3> power_to_bezier(const std::vector<Vec3>& coefficients) {
    require_finite_points(coefficients, "coefficients");
    // [P_i] = M^{-1} [a_i], with M^{-1}[i][j] = C(i,j) / C(n,j) for j <= i: the expansion
    // u^j = sum_{i>=j} C(i,j)/C(n,j) B_{i,n}(u). Only positive terms, no matrix inversion.
    const int n = static_cast<int>(coefficients.size()) - 1;
    std::vector<Vec3> control_points(coefficients.size());
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= i; ++j)
            control_points[static_cast<std::size_t>(i)] +=
                (binomial(i, j) / binomial(n, j)) * coefficients[static_cast<std::size_t>(j)];
    return require_finite_result(control_points, "coefficients");
}

}  // namespace ratbez
