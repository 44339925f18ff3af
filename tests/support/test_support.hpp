#pragma once
// Helpers shared by every core test suite (and tests/openscad): Error checks that name the argument,
// Vec3 / Vec4 comparisons, non-finite constants, a small closed mesh. The suite-specific helpers live in
// bezier_test_support.hpp (exact rational oracles), nurbs_test_support.hpp (random knot vectors, curves,
// surfaces) and solid_test_support.hpp (random rigid motions, solid invariants), all in ratbez::test.

#include <gtest/gtest.h>

#include <exception>
#include <functional>
#include <limits>
#include <string>

#include "ratbez/error.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::test {

inline constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();
inline constexpr double inf_value = std::numeric_limits<double>::infinity();

inline bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// The message of the ratbez::Error thrown by `action`; fails the test (and returns a marker) when nothing
// or something else is thrown.
template <class F>
std::string error_message(F&& action) {
    try {
        action();
    } catch (const Error& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "threw a non-ratbez exception: " << e.what();
        return "<non-ratbez exception>";
    }
    ADD_FAILURE() << "did not throw";
    return "<no ratbez::Error thrown>";
}

// Asserts that `action` throws ratbez::Error whose message starts with "<argument>:".
#define EXPECT_ERROR_NAMING(action, argument)                                              \
    do {                                                                                  \
        const std::string message_ = ::ratbez::test::error_message([&] { (void)(action); }); \
        EXPECT_EQ(message_.rfind(std::string(argument) + ":", 0), 0u) << message_;         \
    } while (false)

// The call throws ratbez::Error whose message starts with "<argument>:" (for EXPECT_TRUE).
inline ::testing::AssertionResult throws_naming(const std::function<void()>& call, const std::string& argument) {
    try {
        call();
    } catch (const Error& e) {
        const std::string message = e.what();
        if (message.rfind(argument + ":", 0) == 0) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "message \"" << message << "\" does not name " << argument;
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure() << "threw a non-ratbez exception: " << e.what();
    }
    return ::testing::AssertionFailure() << "did not throw";
}

// |actual - expected| <= tolerance in the Euclidean norm (for EXPECT_TRUE).
inline ::testing::AssertionResult near(const Vec3& actual, const Vec3& expected, double tolerance) {
    const double d = distance(actual, expected);
    if (d <= tolerance) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") vs ("
                                         << expected.x << ", " << expected.y << ", " << expected.z
                                         << "): distance " << d << " > " << tolerance;
}

// Every coordinate within `tolerance` (one EXPECT_NEAR each, labelled `what`).
inline void expect_near(const Vec3& actual, const Vec3& expected, double tolerance, const std::string& what = "") {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}
inline void expect_near(const Vec4& actual, const Vec4& expected, double tolerance, const std::string& what = "") {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
    EXPECT_NEAR(actual.w, expected.w, tolerance) << what;
}

// The unit tetrahedron, outward by the right-hand rule (counterclockwise seen from outside).
inline Mesh tetrahedron() {
    Mesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

}  // namespace ratbez::test
