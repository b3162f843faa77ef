// Output files written first under hidden names beside their targets, and renamed to the targets
// only by commit(): a failure before it leaves no output and old files untouched, and the
// destructor removes what was not committed.
#pragma once

#include <string>
#include <vector>

namespace candela {

class StagedFiles {
 public:
  StagedFiles() = default;
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  ~StagedFiles();
  // A hidden name beside target, with its extension (which picks the image format), to write to.
  std::string stage(const std::string& target);
  // Renames every staged file to its target, saying so on standard error unless quiet. Throws
  // FileError naming the target that cannot be renamed.
  void commit(bool quiet);

 private:
  struct Staged {
    std::string file, target;
  };
  std::vector<Staged> staged_;
};

// The output path of frame frameIndex: frame 0 keeps the name; later frames of a multi-frame file
// get "-1", "-2", ... before the extension so they do not overwrite each other.
std::string framePath(const std::string& path, int frameIndex);

}  // namespace candela
