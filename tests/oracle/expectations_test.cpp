// The known-divergences file: entries with reasons, comments, and line-numbered errors.
#include "oracle/compare/expectations.h"

#include <gtest/gtest.h>

#include "raster/core/errors.h"

namespace raster::oracle {
namespace {

TEST(Expectations, readsEntriesWithTheirReasonsAndSkipsComments) {
    const auto list = parse_expectations(
        "# header\n\nteapot 16 3   # three samples on the spout's silhouette, see issue 9\n"
        "  flat_cube 1 1 # a reason  \n",
        "oracle.txt");
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0].scene, "teapot");
    EXPECT_EQ(list[0].samples, 16);
    EXPECT_EQ(list[0].max_genuine, 3u);
    EXPECT_EQ(list[0].reason, "three samples on the spout's silhouette, see issue 9");
    EXPECT_EQ(list[0].line, 3);
    EXPECT_EQ(list[1].reason, "a reason");
    EXPECT_EQ(find_expectation(list, "teapot", 16), &list[0]);
    EXPECT_EQ(find_expectation(list, "teapot", 1), nullptr);
}

TEST(Expectations, anEntryWithoutAReasonIsAnError) {
    try {
        parse_expectations("# ok\nteapot 16 3\n", "oracle.txt");
        FAIL();
    } catch (const InputError& error) {
        EXPECT_EQ(error.line(), 2);
        EXPECT_NE(std::string(error.what()).find("reason"), std::string::npos);
    }
    EXPECT_THROW(parse_expectations("teapot 16 3 #   \n", "oracle.txt"), InputError);
}

TEST(Expectations, malformedAndRepeatedEntriesAreErrors) {
    EXPECT_THROW(parse_expectations("teapot sixteen 3 # r\n", "f"), InputError);
    EXPECT_THROW(parse_expectations("teapot 16 # r\n", "f"), InputError);
    EXPECT_THROW(parse_expectations("teapot 16 3 extra # r\n", "f"), InputError);
    EXPECT_THROW(parse_expectations("teapot 0 3 # r\n", "f"), InputError);
    EXPECT_THROW(parse_expectations("teapot 16 3 # r\nteapot 16 4 # again\n", "f"), InputError);
}

}  // namespace
}  // namespace raster::oracle
