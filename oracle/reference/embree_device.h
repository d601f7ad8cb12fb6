// An Embree device whose every error becomes an OracleError: the device error callback records what Embree
// reports, and check() turns it into an exception naming the call that failed.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

namespace raster::oracle {

// Anything the oracle could not do (Embree failed, or ran out of memory). Not an input error: the scene is valid.
class OracleError : public std::runtime_error {
public:
    explicit OracleError(const std::string& message) : std::runtime_error(message) {}
};

// Owns one RTCDevice for its lifetime. The device's error callback records the first error since the last
// check(); check() throws it as "embree: <what>: RTC_ERROR_...: <Embree's message>".
class EmbreeDevice {
public:
    // `config` is Embree's device configuration string (e.g. "threads=2"). Throws OracleError when Embree
    // cannot create the device (unsupported CPU, bad configuration).
    explicit EmbreeDevice(const std::string& config = "");
    ~EmbreeDevice();
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    RTCDevice get() const { return device_; }

    // Throws OracleError if Embree reported an error since the last check; `what` names the step, for the message.
    void check(const std::string& what) const;

    // The name of an Embree error code, e.g. "RTC_ERROR_INVALID_ARGUMENT".
    static const char* error_name(RTCError code);

    struct ErrorLog;  // what the callback writes; defined in the source

private:
    RTCDevice device_ = nullptr;
    std::unique_ptr<ErrorLog> log_;
};

// The Embree device for a thread count, made once per calling thread and kept: creating one starts its task
// scheduler, which cost half of a small scene's comparison (the differential fuzz target compares thousands a
// second), and a device holds no scene of its own. Per thread, so that a device's error log only ever sees its own
// thread's calls.
EmbreeDevice& embree_device_for(int threads);

}  // namespace raster::oracle
