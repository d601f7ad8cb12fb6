// The Embree device wrapper: creation, the error callback and the check that turns recorded errors into throws.
#include "oracle/reference/embree_device.h"

#include <map>
#include <mutex>

namespace raster::oracle {

struct EmbreeDevice::ErrorLog {
    std::mutex mutex;
    RTCError code = RTC_ERROR_NONE;
    std::string message;
};

namespace {

// Embree may call this from any thread (BVH builds run on its task scheduler): keep only the first error.
void record_error(void* user, RTCError code, const char* message) {
    auto* log = static_cast<EmbreeDevice::ErrorLog*>(user);
    std::lock_guard<std::mutex> lock(log->mutex);
    if (log->code != RTC_ERROR_NONE) return;
    log->code = code;
    log->message = message ? message : "";
}

}  // namespace

const char* EmbreeDevice::error_name(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE: return "RTC_ERROR_NONE";
        case RTC_ERROR_UNKNOWN: return "RTC_ERROR_UNKNOWN";
        case RTC_ERROR_INVALID_ARGUMENT: return "RTC_ERROR_INVALID_ARGUMENT";
        case RTC_ERROR_INVALID_OPERATION: return "RTC_ERROR_INVALID_OPERATION";
        case RTC_ERROR_OUT_OF_MEMORY: return "RTC_ERROR_OUT_OF_MEMORY";
        case RTC_ERROR_UNSUPPORTED_CPU: return "RTC_ERROR_UNSUPPORTED_CPU";
        case RTC_ERROR_CANCELLED: return "RTC_ERROR_CANCELLED";
    }
    return "RTC_ERROR_(unknown code)";
}

EmbreeDevice::EmbreeDevice(const std::string& config) : log_(std::make_unique<ErrorLog>()) {
    device_ = rtcNewDevice(config.c_str());
    if (!device_) {
        // Before a device exists the error is only available through the null device.
        const RTCError code = rtcGetDeviceError(nullptr);
        throw OracleError("embree: cannot create a device with configuration \"" + config + "\": " +
                          error_name(code));
    }
    rtcSetDeviceErrorFunction(device_, record_error, log_.get());
}

EmbreeDevice::~EmbreeDevice() {
    if (device_) rtcReleaseDevice(device_);
}

void EmbreeDevice::check(const std::string& what) const {
    std::lock_guard<std::mutex> lock(log_->mutex);
    if (log_->code == RTC_ERROR_NONE) return;
    const std::string message =
        "embree: " + what + ": " + error_name(log_->code) + (log_->message.empty() ? "" : ": " + log_->message);
    log_->code = RTC_ERROR_NONE;
    log_->message.clear();
    throw OracleError(message);
}

EmbreeDevice& embree_device_for(int threads) {
    thread_local std::map<int, std::unique_ptr<EmbreeDevice>> devices;
    std::unique_ptr<EmbreeDevice>& device = devices[threads];
    if (!device) device = std::make_unique<EmbreeDevice>("threads=" + std::to_string(threads));
    return *device;
}

}  // namespace raster::oracle
