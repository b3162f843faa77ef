// Generator matrices for (0,m,2)-nets in base 2 with maximal minimum distance (Grünschloß,
// Hanika, Schwede & Keller 2008, "(t,m,s)-Nets and Maximized Minimum Distance"; pbrt 3e §7.6):
// the 2^m points (i / 2^m, C_m i), i = 0 .. 2^m - 1, are a (0,m,2)-net whose smallest distance
// between two points on the unit torus is as large as the authors' search found among such
// matrices C_m. The figures are the published ones for m = 2 .. 16, as pbrt-v3 transcribes them
// (each column's bits reversed so that the product is the fraction's digits, top-aligned).
#pragma once

#include <cstdint>

namespace candela {

inline constexpr int kMaxMinDistLog2Max = 16;

// The second coordinate C_m i of point i (0 <= i < 2^m, 0 <= m <= kMaxMinDistLog2Max) as a
// 32-bit binary fraction (bit 31 the first digit).
uint32_t maxMinDistBits(uint32_t index, int log2Count);

}  // namespace candela
