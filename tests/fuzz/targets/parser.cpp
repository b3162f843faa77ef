#include <filesystem>

#include "core/error.h"
#include "fuzz/targets/fuzz_targets.h"
#include "fuzz/targets/split_files.h"
#include "parser/parser.h"
#include "parser/scene_builder.h"

namespace candela::fuzz {

// The files of the input are parsed through the SceneBuilder, which records each frame's
// description (nothing is built or rendered, and only the input's own files are read). Errors
// must be located in one of them.
void parser(std::string_view input) {
  std::map<std::string, std::string> files = splitFiles(input);
  SceneFileReader readFile = [&](const std::string& path) {
    auto it = files.find(std::filesystem::path(path).lexically_normal().string());
    if (it == files.end()) throw FileError(path, "no such file");
    return it->second;
  };
  auto ignore = [](const FileLoc&, const std::string&) {};
  int frames = 0;
  SceneBuilder builder([&](SceneDescription&&) { ++frames; }, ignore);
  try {
    parseString(files[kMainFile], kMainFile, builder, ignore, readFile);
    builder.endOfInput({kMainFile, 0, 0});
  } catch (const SceneError& e) {
    // An absolute Include keeps its name as written ("/fuzz//a.pbrt").
    std::string file = std::filesystem::path(e.location().file).lexically_normal().string();
    if (!files.count(file)) broken("a scene error outside the input's files");
  }
  if (frames != builder.framesCompleted()) broken("frames handed over and counted differ");
}

}  // namespace candela::fuzz
