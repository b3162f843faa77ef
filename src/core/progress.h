// Progress of a long job on stderr: a bar with elapsed time and ETA on a terminal, plain lines
// every few seconds otherwise (logs, CI). Safe to update from several threads.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace candela {

class ProgressReporter {
 public:
  enum class Mode { Quiet, Bar, Lines };
  ProgressReporter(int64_t totalWork, std::string title, Mode mode);
  ~ProgressReporter() { done(); }
  void update(int64_t work = 1);
  void done();
  double elapsedSeconds() const;
  static Mode modeFor(bool quiet);  // Bar on a terminal, Lines otherwise

 private:
  void print(int64_t done, bool final);
  int64_t total_;
  std::string title_;
  Mode mode_;
  std::atomic<int64_t> workDone_{0};
  std::chrono::steady_clock::time_point start_;
  std::mutex printMutex_;
  double lastPrint_ = -1e9;
  bool finished_ = false;
};

}  // namespace candela
