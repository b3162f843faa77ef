// Where a file named in a scene lives: relative names are relative to the directory of the scene
// file that names them (as pbrt does); "-" (standard input) and an empty scene file name leave
// them relative to the working directory.
#pragma once

#include <filesystem>
#include <string>

namespace candela {

inline std::string resolveScenePath(const std::string& filename, const std::string& sceneFile) {
  namespace fs = std::filesystem;
  fs::path p(filename);
  if (p.is_absolute() || sceneFile.empty() || sceneFile == "-")
    return p.lexically_normal().string();
  return (fs::path(sceneFile).parent_path() / p).lexically_normal().string();
}

}  // namespace candela
