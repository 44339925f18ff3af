#pragma once
// Private numeric helpers shared by the core sources: index conversion, binomial coefficients,
// compensated summation, number and point formatting for error messages. Not installed, not part of the public API.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "ratbez/error.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// An int that the caller knows is >= 0 (a degree, an order, an index) as a std::size_t.
inline std::size_t to_size(int value) { return static_cast<std::size_t>(value); }

// C(n, k) by the multiplicative formula C(n, i) = C(n, i-1) (n-k+i) / i, in integers while they fit in
// 64 bits (every step is an exact division), so the result is the correctly rounded C(n, k) for n <= 62
// and exact wherever C(n, k) < 2^53 (every n <= 56, as Pascal's triangle by additions). 0 outside 0 <= k <= n.
inline double binomial(int n, int k) {
    if (k < 0 || k > n) return 0.0;
    if (k > n - k) k = n - k;  // C(n, k) = C(n, n-k): fewer, smaller steps
    std::uint64_t exact = 1;
    int i = 1;
    for (; i <= k; ++i) {
        const auto factor = static_cast<std::uint64_t>(n - k + i);
        if (exact > std::numeric_limits<std::uint64_t>::max() / factor) break;
        exact = exact * factor / static_cast<std::uint64_t>(i);
    }
    double result = static_cast<double>(exact);
    for (; i <= k; ++i) result = result * static_cast<double>(n - k + i) / static_cast<double>(i);
    return result;
}

// A sum of many terms with Neumaier's compensation (an improved Kahan summation): the rounding error of
// each addition is carried along and added back at the end, so the result is good to a few ulps of the
// sum however many terms there are (naive summation of 10^5 cells drifts by sqrt(n) ulps and more).
class CompensatedSum {
public:
    void add(double term) {
        const double next = sum_ + term;
        compensation_ += std::abs(sum_) >= std::abs(term) ? (sum_ - next) + term : (term - next) + sum_;
        sum_ = next;
    }
    double value() const { return sum_ + compensation_; }

private:
    double sum_ = 0, compensation_ = 0;
};

// A double in an error message: 12 significant digits, so 0.1 reads "0.1" and 1e-7 does not read "0".
inline std::string number(double value) {
    std::ostringstream out;
    out.precision(12);
    out << value;
    return out.str();
}

// A point in an error message: 9 significant digits per coordinate.
inline std::string format_point(const Vec3& p) {
    std::ostringstream out;
    out.precision(9);
    out << '(' << p.x << ", " << p.y << ", " << p.z << ')';
    return out.str();
}

// A double in an error message about a parameter, where the last digit matters (error.hpp).
using ratbez::exact_number;

// Work space of `size` T on the stack when size <= N, on the heap beyond: evaluation (basis functions,
// partials) is the tessellator's hot path and must not allocate for practical degrees. The stack entries are
// not initialised (T's default constructor aside): every caller writes an entry before reading it.
template <class T, std::size_t N>
class Scratch {
public:
    explicit Scratch(std::size_t size) : size_(size) {
        if (size > N) heap_.resize(size);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
    std::span<T> values() { return {size_ > N ? heap_.data() : fixed_.data(), size_}; }
    T& operator[](std::size_t i) { return size_ > N ? heap_[i] : fixed_[i]; }

private:
    std::size_t size_;
    std::array<T, N> fixed_;
    std::vector<T> heap_;
};

}  // namespace ratbez::detail
