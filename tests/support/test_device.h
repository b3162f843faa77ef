// Test helper: the one Embree device of a test program, as the renderer has one per process.
#pragma once

#include "accel/embree/embree_device.h"

namespace candela::test {

const EmbreeDevice& embreeDevice();

}  // namespace candela::test
