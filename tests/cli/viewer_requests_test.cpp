// `raster view`'s request parsing: every parameter read, every bad value refused with a message naming it and
// quoting what was sent, without a server.
#include "apps/viewer_requests.h"

#include <gtest/gtest.h>

namespace raster::cli {
namespace {

std::string error_of(const QueryParameters& parameters) { return parse_view_request(parameters).error; }

TEST(ViewerRequests, noParametersKeepTheScenesOwnFrame) {
    const ParsedViewRequest parsed = parse_view_request({});
    ASSERT_EQ(parsed.error, "");
    EXPECT_FALSE(parsed.request.shading);
    EXPECT_FALSE(parsed.request.samples);
    EXPECT_FALSE(parsed.request.msaa);
    EXPECT_FALSE(parsed.request.filter);
    EXPECT_EQ(parsed.request.yaw_degrees, 0.0);
    EXPECT_EQ(parsed.request.pitch_degrees, 0.0);
    EXPECT_EQ(parsed.request.distance, 1.0);
}

TEST(ViewerRequests, everyParameterIsRead) {
    const ParsedViewRequest parsed = parse_view_request({{"shading", "flat"}, {"samples", "16"}, {"msaa", "1"},
                                                         {"filter", "anisotropic"}, {"yaw", "-12.5"},
                                                         {"pitch", "30"}, {"distance", "0.75"}});
    ASSERT_EQ(parsed.error, "");
    EXPECT_EQ(parsed.request.shading, ShadingMode::flat);
    EXPECT_EQ(parsed.request.samples, 16);
    EXPECT_EQ(parsed.request.msaa, true);
    EXPECT_EQ(parsed.request.filter, TextureFilter::anisotropic);
    EXPECT_EQ(parsed.request.yaw_degrees, -12.5);
    EXPECT_EQ(parsed.request.pitch_degrees, 30.0);
    EXPECT_EQ(parsed.request.distance, 0.75);
    EXPECT_EQ(parse_view_request({{"shading", "blinn-phong"}, {"msaa", "0"}}).request.msaa, false);
    EXPECT_EQ(parse_view_request({{"shading", "blinn-phong"}}).request.shading, ShadingMode::blinn_phong);
}

TEST(ViewerRequests, theRangesEndsAreAllowed) {
    for (const char* yaw : {"-360", "360"}) EXPECT_EQ(error_of({{"yaw", yaw}}), "") << yaw;
    for (const char* pitch : {"-180", "180"}) EXPECT_EQ(error_of({{"pitch", pitch}}), "") << pitch;
    for (const char* distance : {"0.05", "20"}) EXPECT_EQ(error_of({{"distance", distance}}), "") << distance;
    for (const char* samples : {"1", "16"}) EXPECT_EQ(error_of({{"samples", samples}}), "") << samples;
}

TEST(ViewerRequests, unknownNamesAndValuesAreRefusedByName) {
    EXPECT_EQ(error_of({{"shading", "toon"}}),
              "shading must be unlit, flat, gouraud, phong, blinn-phong, cel or gooch, got 'toon'");
    EXPECT_EQ(error_of({{"shading", "Flat"}}),
              "shading must be unlit, flat, gouraud, phong, blinn-phong, cel or gooch, got 'Flat'");
    EXPECT_EQ(error_of({{"filter", "cubic"}}),
              "filter must be nearest, bilinear, trilinear or anisotropic, got 'cubic'");
    EXPECT_EQ(error_of({{"msaa", "true"}}), "msaa must be 0 or 1, got 'true'");
    EXPECT_EQ(error_of({{"zoom", "2"}}),
              "unknown parameter 'zoom' (known: camera, distance, filter, msaa, pitch, samples, shading, shadows, time, "
              "transparency, yaw)");
    EXPECT_EQ(error_of({{"yaw", "1"}, {"yaw", "2"}}), "parameter 'yaw' is given more than once");
}

TEST(ViewerRequests, theShadowAndTransparencySwitchesTakeTheirWordsOnly) {
    EXPECT_EQ(parse_view_request({{"shadows", "on"}}).request.shadows, true);
    EXPECT_EQ(parse_view_request({{"shadows", "off"}}).request.shadows, false);
    EXPECT_FALSE(parse_view_request({}).request.shadows);
    EXPECT_EQ(error_of({{"shadows", "1"}}), "shadows must be on or off, got '1'");
    EXPECT_EQ(parse_view_request({{"transparency", "sorted"}}).request.transparency, TransparencyChoice::sorted);
    EXPECT_EQ(parse_view_request({{"transparency", "weighted"}}).request.transparency, TransparencyChoice::weighted);
    EXPECT_EQ(parse_view_request({{"transparency", "opaque"}}).request.transparency, TransparencyChoice::opaque);
    EXPECT_FALSE(parse_view_request({}).request.transparency);
    EXPECT_EQ(error_of({{"transparency", "off"}}), "transparency must be sorted, weighted or opaque, got 'off'");
}

TEST(ViewerRequests, samplesOutsideOneToSixteenOrNotWholeAreRefused) {
    EXPECT_EQ(error_of({{"samples", "0"}}), "samples must be in [1, 16], got '0'");
    EXPECT_EQ(error_of({{"samples", "32"}}), "samples must be in [1, 16], got '32'");
    EXPECT_EQ(error_of({{"samples", "-4"}}), "samples must be in [1, 16], got '-4'");
    EXPECT_EQ(error_of({{"samples", "4.0"}}), "samples must be a whole number, got '4.0'");
    EXPECT_EQ(error_of({{"samples", "99999999999999999999"}}),
              "samples must be a whole number, got '99999999999999999999'");
    EXPECT_EQ(error_of({{"samples", ""}}), "samples must be a whole number, got ''");
}

TEST(ViewerRequests, anglesAndDistanceMustBeFiniteNumbersInRange) {
    for (const char* bad : {"nan", "NaN", "inf", "-inf", "1e400", "abc", "", " 1", "1 ", "+1", "1x", "0x10", "1,5"})
        EXPECT_EQ(error_of({{"yaw", bad}}), "yaw must be a finite number, got '" + std::string(bad) + "'") << bad;
    EXPECT_EQ(error_of({{"yaw", "360.5"}}), "yaw must be in [-360, 360] degrees, got '360.5'");
    EXPECT_EQ(error_of({{"yaw", "1e300"}}), "yaw must be in [-360, 360] degrees, got '1e300'");
    EXPECT_EQ(error_of({{"pitch", "-181"}}), "pitch must be in [-180, 180] degrees, got '-181'");
    EXPECT_EQ(error_of({{"distance", "0"}}),
              "distance must be in [0.05, 20] (times the scene's eye-target distance), got '0'");
    EXPECT_EQ(error_of({{"distance", "-1"}}),
              "distance must be in [0.05, 20] (times the scene's eye-target distance), got '-1'");
    EXPECT_EQ(error_of({{"distance", "nan"}}), "distance must be a finite number, got 'nan'");
}

TEST(ViewerRequests, aTimeIsAFiniteNumberOfSecondsWithinAMillion) {
    EXPECT_FALSE(parse_view_request({}).request.time);
    const ParsedViewRequest parsed = parse_view_request({{"time", "1.25"}});
    EXPECT_EQ(parsed.error, "");
    EXPECT_EQ(parsed.request.time, std::optional<double>(1.25));
    EXPECT_EQ(error_of({{"time", "-1000000"}}), "");
    EXPECT_EQ(error_of({{"time", "inf"}}), "time must be a finite number, got 'inf'");
    EXPECT_EQ(error_of({{"time", "2e6"}}), "time must be in [-1e+06, 1e+06] seconds, got '2e6'");
}

TEST(ViewerRequests, aCameraIsAWholeNumberFromZero) {
    EXPECT_EQ(parse_view_request({{"camera", "2"}}).request.camera, std::optional<int>(2));
    EXPECT_EQ(error_of({{"camera", "-1"}}), "camera must be a whole number in [0, 65536], got '-1'");
    EXPECT_EQ(error_of({{"camera", "1.5"}}), "camera must be a whole number in [0, 65536], got '1.5'");
}

TEST(ViewerRequests, whatWasSentIsQuotedShortAndPrintable) {
    EXPECT_EQ(error_of({{"shading", std::string("fl\nat\x01", 6)}}),
              "shading must be unlit, flat, gouraud, phong, blinn-phong, cel or gooch, got 'fl?at?'");
    const std::string message = error_of({{"filter", std::string(1000, 'x')}});
    EXPECT_NE(message.find("got '" + std::string(40, 'x') + "...'"), std::string::npos) << message;
    EXPECT_LT(message.size(), 150u);
}

}  // namespace
}  // namespace raster::cli
