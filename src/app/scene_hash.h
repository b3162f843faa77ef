// What tells pieces of one render from pieces of another: a digest of the scene files' contents,
// and the command-line options that change pixels, for `candela merge` to compare. Included files,
// meshes and textures are not read for it: a farm reads them from one shared file system.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "app/cli_options.h"

namespace candela {

class SceneHash {
 public:
  // Adds one file's text; files are told apart by their lengths, so where one ends matters.
  void add(std::string_view text);
  // Adds the file at path (FileError naming it when it cannot be read).
  void addFile(const std::string& path);
  // 16 hex digits.
  std::string hex() const;

 private:
  uint64_t h_ = 0x9e3779b97f4a7c15ULL;
};

// The options that change pixels besides --spp, --seed and the crop, as "name=value" pairs, so two
// pieces can be compared and a refusal can say which option differed. half: the EXR is stored in
// half floats (--half or the Film's "half").
std::string imageOptionsText(const CliOptions& cli, bool half);

}  // namespace candela
