#include "core/interrupt.h"

#include <atomic>
#include <csignal>
#include <string>

namespace candela {

namespace {

// Lock-free, so that the handler may store to it (async-signal-safe).
std::atomic<int> receivedSignal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void recordSignal(int signal) {
  receivedSignal.store(signal, std::memory_order_relaxed);
  // The next one is not ours to soften: a render stuck outside any loop still stops.
  std::signal(signal, SIG_DFL);
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") + (signal == SIGINT    ? "SIGINT"
                                                           : signal == SIGTERM ? "SIGTERM"
                                                                               : "a signal")),
      signal_(signal) {}

void installInterruptHandlers() {
  std::signal(SIGINT, recordSignal);
  std::signal(SIGTERM, recordSignal);
}

int pendingInterrupt() { return receivedSignal.load(std::memory_order_relaxed); }

void throwIfInterrupted() {
  if (int s = pendingInterrupt()) throw Interrupted(s);
}

}  // namespace candela
