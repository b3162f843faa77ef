// The CSV of error against run time that --error-log appends to, one row per pass.
#pragma once

#include <cstdio>
#include <string>

#include "film/error_metrics.h"
#include "integrators/progressive_render.h"

namespace candela {

class ErrorLog {
 public:
  static constexpr const char* kHeader =
      "seconds,spp,rays,mse,relmse,rmse,maxerr,relmse_ci95,relmse_predicted,samples";
  // Opens for appending; writes the header when the file is new or empty. Throws FileError.
  explicit ErrorLog(const std::string& path);
  ~ErrorLog();
  ErrorLog(const ErrorLog&) = delete;
  ErrorLog& operator=(const ErrorLog&) = delete;
  void append(const PassReport& pass, const ErrorMetrics& m);

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
};

}  // namespace candela
