#include "ratbez/error.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <type_traits>

namespace ratbez {
namespace {

static_assert(std::is_nothrow_copy_constructible_v<Error>, "an exception is copied while it is thrown");

TEST(Error, CarriesArgumentAndReasonBesideTheJoinedMessage) {
    const Error error("radius", "must be greater than 0");
    EXPECT_STREQ(error.what(), "radius: must be greater than 0");
    EXPECT_EQ(error.argument(), "radius");
    EXPECT_EQ(error.reason(), "must be greater than 0");

    // A reason may itself contain ": " (a nested error's text); the argument ends where it was given.
    const Error nested("solid", "face 2: sides: side v_min has no edge");
    EXPECT_EQ(nested.argument(), "solid");
    EXPECT_EQ(nested.reason(), "face 2: sides: side v_min has no edge");

    const Error copy = nested;  // the parts follow the copied text
    EXPECT_EQ(copy.argument(), "solid");
    EXPECT_EQ(copy.reason(), "face 2: sides: side v_min has no edge");
}

TEST(Error, FailAndRequireThrowTheTwoParts) {
    try {
        require(false, "points[2]", [] { return std::string("must be finite"); });
        FAIL() << "require(false, ...) must throw";
    } catch (const Error& e) {
        EXPECT_EQ(e.argument(), "points[2]");
        EXPECT_EQ(e.reason(), "must be finite");
        EXPECT_STREQ(e.what(), "points[2]: must be finite");
    }
    try {
        require_finite(std::numeric_limits<double>::infinity(), "height");
        FAIL() << "require_finite(inf) must throw";
    } catch (const Error& e) {
        EXPECT_EQ(e.argument(), "height");
        EXPECT_EQ(e.reason(), "must be a finite number");
    }
}

TEST(Error, UnderPutsTheArgumentBelowAPath) {
    const Error error("weights", "element 1 is not a finite number");
    const Error rooted = error.under("shape.profile[1]");
    EXPECT_EQ(rooted.argument(), "shape.profile[1].weights");
    EXPECT_EQ(rooted.reason(), "element 1 is not a finite number");
    EXPECT_STREQ(rooted.what(), "shape.profile[1].weights: element 1 is not a finite number");
    EXPECT_STREQ(error.under("").what(), error.what());
}

TEST(Error, RenamedGivesTheCallersNameToTheArgumentAndItsParts) {
    EXPECT_STREQ(Error("curves", "must not be empty").renamed("curves", "profiles").what(), "profiles: must not be empty");
    EXPECT_STREQ(Error("curves[2]", "is open").renamed("curves", "path").what(), "path[2]: is open");
    EXPECT_STREQ(Error("curves.weights", "bad").renamed("curves", "profiles[1]").what(), "profiles[1].weights: bad");
    // A longer name that merely starts with `from`, and any other argument, are kept.
    EXPECT_STREQ(Error("curvesx", "bad").renamed("curves", "path").what(), "curvesx: bad");
    EXPECT_STREQ(Error("tolerance", "bad").renamed("curves", "path").what(), "tolerance: bad");
}

}  // namespace
}  // namespace ratbez
