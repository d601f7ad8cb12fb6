// The oracle's interval arithmetic where bounds are unbounded: no operation may turn an unbounded operand into NaN
// bounds, which every comparison after reads as an empty interval.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "oracle/reference/interval.h"

namespace {

using raster::oracle::Interval;
using raster::oracle::Interval3;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

TEST(Interval, aNanAllowanceWidensToEverything) {
    // An unbounded barycentric next to a vertex coordinate of exactly 0: the rounding allowance's magnitude product
    // is inf * 0.
    const Interval unbounded = Interval(0.5).widened(kInfinity);
    const double allowance = unbounded.magnitude() * Interval(0.0).magnitude();
    ASSERT_TRUE(std::isnan(allowance));
    const Interval widened = Interval(1.0, 2.0).widened(allowance);
    EXPECT_EQ(widened.lo, -kInfinity);
    EXPECT_EQ(widened.hi, kInfinity);
    EXPECT_TRUE(widened.contains(1.5));
}

TEST(Interval, aFiniteAllowanceWidensBothSides) {
    const Interval widened = Interval(1.0, 2.0).widened(0.25);
    EXPECT_EQ(widened.lo, 0.75);
    EXPECT_EQ(widened.hi, 2.25);
}

TEST(Interval, anUnboundedProductStaysContainedAndPositive) {
    // The light test after it: hi > 0 must hold for an interval that can be anything.
    const Interval3 everything(Interval::everything(), Interval::everything(), Interval::everything());
    const Interval squared = dot(everything, everything).widened(kInfinity * 0.0);
    EXPECT_TRUE(squared.hi > 0.0);
    EXPECT_TRUE(squared.contains(224.654));
}

}  // namespace
