// The Embree device wrapper: every Embree error surfaces as an OracleError naming the call and Embree's message.
#include "oracle/reference/embree_device.h"

#include <gtest/gtest.h>

namespace raster::oracle {
namespace {

TEST(EmbreeDevice, aHealthyDevicePassesItsCheck) {
    EmbreeDevice device("threads=1");
    ASSERT_NE(device.get(), nullptr);
    RTCScene scene = rtcNewScene(device.get());
    rtcCommitScene(scene);
    EXPECT_NO_THROW(device.check("rtcCommitScene"));
    rtcReleaseScene(scene);
}

TEST(EmbreeDevice, anEmbreeErrorBecomesAnOracleErrorNamingTheCallAndTheReason) {
    EmbreeDevice device;
    EXPECT_EQ(rtcNewGeometry(device.get(), static_cast<RTCGeometryType>(9999)), nullptr);
    try {
        device.check("rtcNewGeometry");
        FAIL() << "the error was not reported";
    } catch (const OracleError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("embree: rtcNewGeometry: RTC_ERROR_"), std::string::npos) << message;
        EXPECT_NE(message.find("invalid geometry type"), std::string::npos) << message;
    }
}

TEST(EmbreeDevice, anErrorIsReportedOnceThenCleared) {
    EmbreeDevice device;
    rtcNewGeometry(device.get(), static_cast<RTCGeometryType>(9999));
    EXPECT_THROW(device.check("first"), OracleError);
    EXPECT_NO_THROW(device.check("second"));
}

TEST(EmbreeDevice, errorCodesHaveTheirEmbreeNames) {
    EXPECT_STREQ(EmbreeDevice::error_name(RTC_ERROR_OUT_OF_MEMORY), "RTC_ERROR_OUT_OF_MEMORY");
    EXPECT_STREQ(EmbreeDevice::error_name(RTC_ERROR_INVALID_ARGUMENT), "RTC_ERROR_INVALID_ARGUMENT");
}

}  // namespace
}  // namespace raster::oracle
