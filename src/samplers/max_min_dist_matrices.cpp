#include "samplers/max_min_dist_matrices.h"

#include <array>
#include <cstddef>

namespace candela {

namespace {

// C_m's columns, column j giving the digits contributed by bit j of i, top-aligned. For m = 1
// the published table (as pbrt-v3 carries it) has its single 1 outside the first column, which
// puts both points at y = 0 and is no net; C_1 = (1) is the (0,1,2)-net's only matrix.
constexpr std::array<std::array<uint32_t, kMaxMinDistLog2Max>, kMaxMinDistLog2Max + 1> kColumns = {{
    {},                                                                                    // m = 0
    {0x80000000},                                                                          // m = 1
    {0xc0000000, 0x80000000},                                                              // m = 2
    {0xa0000000, 0x40000000, 0x80000000},                                                  // m = 3
    {0xc0000000, 0x50000000, 0x20000000, 0x30000000},                                      // m = 4
    {0x88000000, 0x58000000, 0x20000000, 0x40000000, 0x80000000},                          // m = 5
    {0xe0000000, 0x60000000, 0x28000000, 0x10000000, 0x18000000, 0x04000000},              // m = 6
    {0x82000000, 0x44000000, 0x2c000000, 0x10000000, 0x20000000, 0x40000000, 0x80000000},  // m = 7
    {0x80000000, 0x70000000, 0x30000000, 0x14000000, 0x08000000, 0x0c000000, 0x02000000,
     0x01000000},  // m = 8
    {0xc0000000, 0x41000000, 0x22000000, 0x16000000, 0x08000000, 0x10000000, 0x20000000, 0x40800000,
     0x80000000},  // m = 9
    {0x80000000, 0x40000000, 0x20000000, 0x18000000, 0x08000000, 0x1c000000, 0x1e000000, 0x03000000,
     0x00800000, 0x00400000},  // m = 10
    {0x80000000, 0x60400000, 0x20800000, 0x11000000, 0x0b000000, 0x04000000, 0x08000000, 0x10000000,
     0x20000000, 0x40000000, 0x00200000},  // m = 11
    {0x80000000, 0x40000000, 0x20000000, 0x1c000000, 0x0c000000, 0x05000000, 0x02000000, 0x03000000,
     0x00800000, 0x00400000, 0x00200000, 0x00100000},  // m = 12
    {0x80000000, 0x40000000, 0x30200000, 0x10400000, 0x08800000, 0x05800000, 0x02000000, 0x04000000,
     0x08000000, 0x10000000, 0x20000000, 0x00100000, 0x00080000},  // m = 13
    {0x80000000, 0x40000000, 0x20000000, 0x10000000, 0x0e000000, 0x06000000, 0x02800000, 0x01000000,
     0x01800000, 0x00400000, 0x00200000, 0x00100000, 0x00080000, 0x00040000},  // m = 14
    {0x80000000, 0x40000000, 0x20000000, 0x18100000, 0x08200000, 0x04400000, 0x02c00000, 0x01000000,
     0x02000000, 0x04000000, 0x08000000, 0x10000000, 0x00080000, 0x00040000, 0x00020000},  // m = 15
    {0x80000000, 0x40000000, 0x20000000, 0x10000000, 0x08000000, 0x07000000, 0x03000000, 0x01400000,
     0x00800000, 0x00c00000, 0x00200000, 0x00100000, 0x00080000, 0x00040000, 0x00020000,
     0x00010000},  // m = 16
}};

}  // namespace

uint32_t maxMinDistBits(uint32_t index, int log2Count) {
  const auto& columns = kColumns[std::size_t(log2Count)];
  uint32_t bits = 0;
  for (int j = 0; index != 0 && j < log2Count; index >>= 1, ++j)
    if (index & 1u) bits ^= columns[std::size_t(j)];
  return bits;
}

}  // namespace candela
