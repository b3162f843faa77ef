#include "accel/embree/embree_device.h"

#include <embree3/rtcore.h>

#if defined(__SSE3__) || defined(__x86_64__)
#include <pmmintrin.h>
#include <xmmintrin.h>
#define CANDELA_HAVE_SSE_CONTROL 1
#endif

namespace candela {

namespace {

const char* errorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_UNKNOWN:
      return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
  }
  return "unrecognised error code";
}

// Embree calls this on the failing thread; exceptions must not cross Embree's C frames, so the
// message is stored and EmbreeDevice::check throws it after the call returns.
void errorCallback(void* userPtr, RTCError code, const char* message) {
  const auto* device = static_cast<const EmbreeDevice*>(userPtr);
  device->recordError(std::string(errorName(code)) + (message ? std::string(": ") + message : ""));
}

}  // namespace

EmbreeDevice::EmbreeDevice(const std::string& config)
    : config_(config.empty() ? kDefaultConfig : config) {
  device_ = rtcNewDevice(config_.c_str());
  if (!device_) {
    RTCError code = rtcGetDeviceError(nullptr);
    throw EmbreeError("rtcNewDevice(\"" + config_ + "\") failed: " + errorName(code));
  }
  rtcSetDeviceErrorFunction(device_, errorCallback, this);
}

EmbreeDevice::~EmbreeDevice() {
  if (device_) rtcReleaseDevice(device_);
}

void EmbreeDevice::check(const std::string& what) const {
  RTCError code = rtcGetDeviceError(device_);
  if (code == RTC_ERROR_NONE) return;
  std::string message = lastMessage();
  throw EmbreeError("Embree: " + what + " failed: " + errorName(code) +
                    (message.empty() ? "" : " (" + message + ")"));
}

std::string EmbreeDevice::lastMessage() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return lastMessage_;
}

void EmbreeDevice::recordError(const std::string& message) const {
  std::lock_guard<std::mutex> lock(mutex_);
  lastMessage_ = message;
}

void enableFlushToZero() {
#ifdef CANDELA_HAVE_SSE_CONTROL
  _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
  _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
#endif
}

}  // namespace candela
