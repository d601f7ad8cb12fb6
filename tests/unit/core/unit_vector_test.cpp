// Unit vectors of any finite size: ordinary vectors keep the plain v / |v| bits, and vectors whose squared length
// float cannot hold (past 1.8e19, under 1e-19) give the direction of the same vector at an ordinary size.
#include "raster/core/unit_vector.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace raster {
namespace {

TEST(UnitVector, anOrdinaryVectorKeepsThePlainQuotientsBits) {
    for (const glm::vec3 v : {glm::vec3(3, 4, 12), glm::vec3(-0.1f, 2e-5f, 7.5f), glm::vec3(1e18f, -3e17f, 2e17f)}) {
        const glm::vec3 plain = v / std::sqrt(glm::dot(v, v));
        EXPECT_EQ(unit_or_zero(v), plain);
    }
}

TEST(UnitVector, aHugeOrTinyVectorPointsWhereItsPowerOfTwoMultipleAtUnitSizeDoes) {
    const glm::vec3 base(0.3f, -0.5f, 0.8125f);
    const glm::vec3 expected = unit_or_zero(base);
    for (const int exponent : {70, 100, 126, -70, -100, -126, -140}) {
        // Multiplying by a power of two is exact (down to -140, where some bits of 0.3 are still kept: compare
        // directions, not bits, there).
        const glm::vec3 v(std::ldexp(base.x, exponent), std::ldexp(base.y, exponent), std::ldexp(base.z, exponent));
        const glm::vec3 unit = unit_or_zero(v);
        EXPECT_NEAR(glm::length(unit), 1.0f, 1e-6f) << exponent;
        if (exponent > -126) EXPECT_EQ(unit, expected) << exponent;
        else EXPECT_GT(glm::dot(unit, expected), 0.9999f) << exponent;
    }
}

TEST(UnitVector, zeroAndNonFiniteVectorsGiveZero) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(unit_or_zero(glm::vec3(0.0f)), glm::vec3(0.0f));
    EXPECT_EQ(unit_or_zero(glm::vec3(inf, 0, 0)), glm::vec3(0.0f));
    EXPECT_EQ(unit_or_zero(glm::vec3(nan, 1, 0)), glm::vec3(0.0f));
}

}  // namespace
}  // namespace raster
