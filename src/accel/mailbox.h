// Mailboxing for aggregates whose leaves share items (grid voxels, kd-tree leaves): a ray that
// meets the same item in several voxels or leaves tests it once (lrt draft §4.3, "This is why we
// need mailboxing").
//
// The draft stores the id of the last ray tested in each primitive and numbers rays from a global
// counter: with several threads tracing at once, rays overwrite each other's ids (its footnote 2)
// and the counter overflows after 2^31 rays (exercise 4.14). Here the mailbox belongs to the query
// instead: a small direct-mapped cache of recently tested item indices that lives on the stack of
// one intersect() call, so nothing is shared between threads and nothing is ever reset. A
// collision evicts an entry; the item is then only tested again, which is wasted work, never a
// wrong answer (testing an item twice gives the same hit or miss).
#pragma once

#include <cstdint>

namespace candela {

class RayMailbox {
 public:
  // True when item was already tested by this query; otherwise records it and returns false.
  bool testedBefore(uint32_t item) {
    uint32_t& slot = slots_[hash(item)];
    if (slot == item + 1) return true;
    slot = item + 1;  // 0 means an empty slot
    return false;
  }

 private:
  static constexpr int kSlots = 32;  // a power of two; 128 bytes, one or two cache lines
  static uint32_t hash(uint32_t item) { return (item * 0x9E3779B1u) >> (32 - 5); }
  uint32_t slots_[kSlots] = {};
};

}  // namespace candela
