#include "app/error_log.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/error.h"

namespace candela {

ErrorLog::ErrorLog(const std::string& path) : path_(path) {
  std::error_code ec;
  bool fresh = !std::filesystem::exists(path, ec) || std::filesystem::file_size(path, ec) == 0;
  file_ = std::fopen(path.c_str(), "a");
  if (!file_) {
    std::string why = "cannot open for appending: ";
    throw FileError(path, why.append(std::strerror(errno)));
  }
  if (fresh) std::fprintf(file_, "%s\n", kHeader);
  std::fflush(file_);
}

ErrorLog::~ErrorLog() {
  if (file_) std::fclose(file_);
}

void ErrorLog::append(const PassReport& pass, const ErrorMetrics& m) {
  unsigned long long rays = pass.total.rays.intersectionRays + pass.total.rays.shadowRays;
  std::fprintf(file_, "%.6f,%d,%llu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%llu\n", pass.seconds, pass.spp,
               rays, m.mse, m.relmse, m.rmse, m.maxAbsError, m.relmseCi95, m.relmseFromVariance,
               (unsigned long long)pass.total.samples);
  // Flushed per row, so a log of an interrupted run is still readable.
  if (std::fflush(file_) != 0) throw FileError(path_, "write failed");
}

}  // namespace candela
