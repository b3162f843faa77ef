#include "app/staged_files.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "core/error.h"

namespace candela {

namespace fs = std::filesystem;

StagedFiles::~StagedFiles() {
  for (const Staged& s : staged_) {
    std::error_code ec;
    fs::remove(s.file, ec);
  }
}

std::string StagedFiles::stage(const std::string& target) {
  const fs::path t(target);
  // Built with += rather than "." + string: GCC 12 warns falsely (-Wrestrict) about the latter.
  std::string name = ".";
  name += t.stem().string();
  name += ".partial-" + std::to_string(::getpid()) + "-" + std::to_string(staged_.size());
  name += t.extension().string();
  std::string file = (t.parent_path() / name).string();
  staged_.push_back({file, target});
  return file;
}

void StagedFiles::commit(bool quiet) {
  for (const Staged& s : staged_) {
    std::error_code ec;
    fs::rename(s.file, s.target, ec);
    if (ec) throw FileError(s.target, "cannot rename '" + s.file + "' to it: " + ec.message());
    if (!quiet) std::fprintf(stderr, "Wrote %s\n", s.target.c_str());
  }
  staged_.clear();
}

std::string framePath(const std::string& path, int frameIndex) {
  if (frameIndex == 0) return path;
  fs::path p(path);
  fs::path ext = p.extension();
  p.replace_extension();
  p += "-";
  p += std::to_string(frameIndex);
  p += ext;
  return p.string();
}

}  // namespace candela
