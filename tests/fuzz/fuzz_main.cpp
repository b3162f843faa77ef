// libFuzzer's entry point for one target of targets/fuzz_targets.h, chosen at compile time
// (CANDELA_FUZZ_TARGET names the function).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/targets/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  candela::fuzz::CANDELA_FUZZ_TARGET(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
