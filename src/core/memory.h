// A bump allocator for per-sample temporaries (BSDFs), freed all at once after each sample
// (lrt draft App. A.2.4). One per worker task, never shared between threads.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace candela {

class MemoryArena {
 public:
  explicit MemoryArena(size_t blockSize = 32768) : blockSize_(blockSize) {}
  MemoryArena(const MemoryArena&) = delete;
  MemoryArena& operator=(const MemoryArena&) = delete;

  void* alloc(size_t n) {
    constexpr size_t align = alignof(std::max_align_t);
    n = (n + align - 1) & ~(align - 1);
    if (offset_ + n > current_.size) startBlock(n);
    void* p = current_.ptr + offset_;
    offset_ += n;
    return p;
  }
  // Objects made here must be trivially destructible or need no destruction: no destructor runs.
  template <typename T, typename... Args>
  T* make(Args&&... args) {
    return new (alloc(sizeof(T))) T(std::forward<Args>(args)...);
  }
  void reset() {
    offset_ = 0;
    for (auto& b : used_) available_.push_back(b);
    used_.clear();
  }
  ~MemoryArena() {
    for (auto& b : used_) ::operator delete(b.ptr, std::align_val_t(alignof(std::max_align_t)));
    for (auto& b : available_)
      ::operator delete(b.ptr, std::align_val_t(alignof(std::max_align_t)));
    if (current_.ptr) ::operator delete(current_.ptr, std::align_val_t(alignof(std::max_align_t)));
  }

 private:
  struct Block {
    char* ptr = nullptr;
    size_t size = 0;
  };
  // A fresh current block of at least n bytes. Out of line: inlined, its vector code made every
  // allocating caller (a BSDF per path vertex) save and restore registers on its common path.
  [[gnu::noinline]] void startBlock(size_t n) {
    if (current_.ptr) used_.push_back(current_);
    current_ = takeBlock(std::max(n, blockSize_));
    offset_ = 0;
  }
  Block takeBlock(size_t n) {
    for (size_t i = 0; i < available_.size(); ++i)
      if (available_[i].size >= n) {
        Block b = available_[i];
        available_.erase(available_.begin() + long(i));
        return b;
      }
    return Block{static_cast<char*>(::operator new(n, std::align_val_t(alignof(std::max_align_t)))),
                 n};
  }
  size_t blockSize_;
  Block current_;
  size_t offset_ = 0;
  std::vector<Block> used_, available_;
};

}  // namespace candela
