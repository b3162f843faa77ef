// An Embree device (DESIGN.md: intersection is Embree's). Embree types stay out of this header so
// that code above the aggregates never sees them.
#pragma once

#include <mutex>
#include <stdexcept>
#include <string>

struct RTCDeviceTy;  // Embree's RTCDevice is RTCDeviceTy*

namespace candela {

// An Embree call failed; what() names the call, Embree's error code and its message.
class EmbreeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class EmbreeDevice {
 public:
  // The configuration used when none is given. The AVX-512 code path of Debian's Embree 3.13.5
  // hangs in some queries on the CPUs we run on; AVX2 passes Embree's own tests at the same speed
  // and gives the same results on machines with and without AVX-512 (notes/dependencies.md §3).
  static constexpr const char* kDefaultConfig = "isa=avx2";

  // config: an Embree device configuration string ("" for kDefaultConfig). Throws EmbreeError
  // when Embree cannot create the device.
  explicit EmbreeDevice(const std::string& config = "");
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDeviceTy* handle() const { return device_; }
  const std::string& config() const { return config_; }

  // Throws EmbreeError if an Embree call made by this thread on this device failed since the
  // last check (Embree keeps one error code per thread); what names the call checked.
  void check(const std::string& what) const;
  // The message of the latest error Embree reported through its callback, from any thread.
  std::string lastMessage() const;
  // For the error callback only: remembers the message (Embree may call it from any thread).
  void recordError(const std::string& message) const;

 private:
  RTCDeviceTy* device_ = nullptr;
  std::string config_;
  mutable std::mutex mutex_;
  mutable std::string lastMessage_;
};

// Sets flush-to-zero and denormals-are-zero in this thread's SSE control register, as Embree
// recommends for speed (denormals in traversal are slow; Embree warns when they are not set).
// The mode is per thread: every thread that traces rays (each TBB worker of the renderer) should
// call it once before tracing. It changes results only for values below FLT_MIN (1.2e-38).
void enableFlushToZero();

}  // namespace candela
