// SIGINT and SIGTERM during a render: the handler only records the signal; long loops see it
// through ProgressReporter::update, which throws Interrupted, and the exception unwinds to the
// command's main, which removes what it had staged and exits 128 + the signal (130, 143). A
// second signal takes the default action at once. Signal handlers are per process, so the
// recorded signal is the one piece of process-wide state.
#pragma once

#include <stdexcept>

namespace candela {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

// Installs the handlers for SIGINT and SIGTERM (the command does, once, at start).
void installInterruptHandlers();
// The signal received since, or 0.
int pendingInterrupt();
// Throws Interrupted when a signal was received.
void throwIfInterrupted();

}  // namespace candela
