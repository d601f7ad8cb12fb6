// The property tests' main: 1000 cases per property unless RC_PARAMS says otherwise (the soak sets max_success).
#include <cstdlib>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    // RapidCheck reads RC_PARAMS when a property first runs; an explicit setting always wins (overwrite = 0).
    setenv("RC_PARAMS", "max_success=1000", 0);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
