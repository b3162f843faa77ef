#include "support/test_device.h"

namespace candela::test {

const EmbreeDevice& embreeDevice() {
  static EmbreeDevice device;
  return device;
}

}  // namespace candela::test
