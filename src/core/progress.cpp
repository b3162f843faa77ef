#include "core/progress.h"

#include <unistd.h>

#include <cstdio>

#include "core/interrupt.h"

namespace candela {

ProgressReporter::ProgressReporter(int64_t totalWork, std::string title, Mode mode)
    : total_(std::max<int64_t>(1, totalWork)),
      title_(std::move(title)),
      mode_(mode),
      start_(std::chrono::steady_clock::now()) {}

ProgressReporter::Mode ProgressReporter::modeFor(bool quiet) {
  if (quiet) return Mode::Quiet;
  return isatty(STDERR_FILENO) ? Mode::Bar : Mode::Lines;
}

double ProgressReporter::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressReporter::update(int64_t work) {
  // Every long loop reports progress: where an interrupt is noticed (core/interrupt.h).
  throwIfInterrupted();
  int64_t now = workDone_.fetch_add(work) + work;
  if (mode_ == Mode::Quiet) return;
  double t = elapsedSeconds();
  double interval = mode_ == Mode::Bar ? 0.25 : 5.0;
  if (t - lastPrint_ < interval) return;  // racy read is fine: only limits the print rate
  std::unique_lock<std::mutex> lock(printMutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_) return;
  lastPrint_ = t;
  print(now, false);
}

void ProgressReporter::done() {
  std::lock_guard<std::mutex> lock(printMutex_);
  if (finished_) return;
  finished_ = true;
  if (mode_ != Mode::Quiet) print(workDone_.load(), true);
}

void ProgressReporter::print(int64_t done, bool final) {
  double t = elapsedSeconds();
  double fraction = std::min(1.0, double(done) / double(total_));
  double eta = fraction > 0 ? t / fraction - t : 0;
  if (mode_ == Mode::Bar) {
    const int width = 40;
    int filled = int(fraction * width);
    std::string bar(size_t(filled), '+');
    bar.resize(width, ' ');
    std::fprintf(stderr, "\r%s [%s] %5.1f%% (%.1fs|%.1fs)%s", title_.c_str(), bar.c_str(),
                 100 * fraction, t, final ? t : eta, final ? "\n" : "");
  } else {
    if (final)
      std::fprintf(stderr, "%s: done in %.1fs\n", title_.c_str(), t);
    else
      std::fprintf(stderr, "%s: %5.1f%% after %.1fs, about %.1fs left\n", title_.c_str(),
                   100 * fraction, t, eta);
  }
  std::fflush(stderr);
}

}  // namespace candela
